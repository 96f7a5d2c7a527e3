# pool:math/div_1e4 — $out = round(10000 $a / $b) by long division, halves away from zero.
# Reads: $a pool.math (|10000 $a / $b| < 2^31), $b pool.math (1..200000000).
# Writes: $out pool.math; temporaries #div_1e4.n #div_1e4.d pool.math.
# Each remainder times 10 stays below 2^31, so the quotient is exact for any such $a.
scoreboard players operation #div_1e4.n pool.math = $a pool.math
execute if score #div_1e4.n pool.math matches ..-1 run scoreboard players operation #div_1e4.n pool.math *= #-1 pool.const
scoreboard players operation $out pool.math = #div_1e4.n pool.math
scoreboard players operation $out pool.math /= $b pool.math
scoreboard players operation #div_1e4.n pool.math %= $b pool.math
function pool:math/div_1e4/digit
function pool:math/div_1e4/digit
function pool:math/div_1e4/digit
function pool:math/div_1e4/digit
scoreboard players operation #div_1e4.n pool.math *= #2 pool.const
execute if score #div_1e4.n pool.math >= $b pool.math run scoreboard players add $out pool.math 1
execute if score $a pool.math matches ..-1 run scoreboard players operation $out pool.math *= #-1 pool.const
