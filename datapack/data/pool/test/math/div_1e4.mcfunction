# pool:math/div_1e4: round(10000 $a / $b) by long division, halves away from zero.
scoreboard players set $a pool.math 7
scoreboard players set $b pool.math 3
function pool:math/div_1e4
assert score $out pool.math matches 23333
scoreboard players set $a pool.math -1
function pool:math/div_1e4
assert score $out pool.math matches -3333
# 10000 / 20000 = 0.5: away from zero
scoreboard players set $a pool.math 1
scoreboard players set $b pool.math 20000
function pool:math/div_1e4
assert score $out pool.math matches 1
scoreboard players set $a pool.math -1
function pool:math/div_1e4
assert score $out pool.math matches -1
