# pool:math/div_round: round($a / $b) for $b > 0, halves away from zero (mirror-symmetric).
scoreboard players set $a pool.math 7
scoreboard players set $b pool.math 2
function pool:math/div_round
assert score $out pool.math matches 4
scoreboard players set $a pool.math -7
function pool:math/div_round
assert score $out pool.math matches -4
scoreboard players set $a pool.math -6
scoreboard players set $b pool.math 4
function pool:math/div_round
assert score $out pool.math matches -2
scoreboard players set $a pool.math 5
scoreboard players set $b pool.math 7
function pool:math/div_round
assert score $out pool.math matches 1
scoreboard players set $a pool.math 2000000000
scoreboard players set $b pool.math 3
function pool:math/div_round
assert score $out pool.math matches 666666667
