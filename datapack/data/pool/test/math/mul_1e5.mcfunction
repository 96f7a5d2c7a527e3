# pool:math/mul_1e5: round($a * $b / 100000), halves away from zero, products far past 2^31.
scoreboard players set $a pool.math 21000000
scoreboard players set $b pool.math 100000
function pool:math/mul_1e5
assert score $out pool.math matches 21000000
scoreboard players set $a pool.math -21000000
scoreboard players set $b pool.math 99999
function pool:math/mul_1e5
assert score $out pool.math matches -20999790
scoreboard players set $a pool.math 1
scoreboard players set $b pool.math 50000
function pool:math/mul_1e5
assert score $out pool.math matches 1
scoreboard players set $a pool.math -1
function pool:math/mul_1e5
assert score $out pool.math matches -1
