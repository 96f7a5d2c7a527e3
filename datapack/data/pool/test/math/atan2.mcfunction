# pool:math/atan2: centidegrees in (-18000, 18000], counter-clockwise from +x towards +z; 0 for (0, 0).
scoreboard players set $x pool.math 1
scoreboard players set $z pool.math 0
function pool:math/atan2
assert score $out pool.math matches 0
scoreboard players set $x pool.math 0
scoreboard players set $z pool.math 1
function pool:math/atan2
assert score $out pool.math matches 9000
scoreboard players set $x pool.math -1
scoreboard players set $z pool.math 0
function pool:math/atan2
assert score $out pool.math matches 18000
scoreboard players set $x pool.math -5
scoreboard players set $z pool.math -5
function pool:math/atan2
assert score $out pool.math matches -13500
# atan2(4, 3) = 53.1301 degrees
scoreboard players set $x pool.math 3000000
scoreboard players set $z pool.math 4000000
function pool:math/atan2
assert score $out pool.math matches 5312..5314
scoreboard players set $x pool.math 0
scoreboard players set $z pool.math 0
function pool:math/atan2
assert score $out pool.math matches 0
