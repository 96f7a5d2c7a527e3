# pool:math/normalize: unit vector x 10000 and length; mirrored input gives mirrored output.
scoreboard players set $x pool.math 3
scoreboard players set $z pool.math 4
function pool:math/normalize
assert score $ux pool.math matches 6000
assert score $uz pool.math matches 8000
assert score $len pool.math matches 5
scoreboard players set $x pool.math -300000
scoreboard players set $z pool.math 400000
function pool:math/normalize
assert score $ux pool.math matches -6000
assert score $uz pool.math matches 8000
assert score $len pool.math matches 499950..500050
scoreboard players set $x pool.math 0
scoreboard players set $z pool.math -7
function pool:math/normalize
assert score $ux pool.math matches 0
assert score $uz pool.math matches -10000
assert score $len pool.math matches 7
# the zero vector has no direction: all three are 0
scoreboard players set $x pool.math 0
scoreboard players set $z pool.math 0
function pool:math/normalize
assert score $ux pool.math matches 0
assert score $uz pool.math matches 0
assert score $len pool.math matches 0
