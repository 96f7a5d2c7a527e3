# pool:math/div_1e4/digit — one decimal digit of pool:math/div_1e4's long division.
# Reads/writes: $out (quotient so far), #div_1e4.n (remainder) pool.math; temporary #div_1e4.d
# pool.math.
scoreboard players operation #div_1e4.n pool.math *= #10 pool.const
scoreboard players operation #div_1e4.d pool.math = #div_1e4.n pool.math
scoreboard players operation #div_1e4.d pool.math /= $b pool.math
scoreboard players operation #div_1e4.n pool.math %= $b pool.math
scoreboard players operation $out pool.math *= #10 pool.const
scoreboard players operation $out pool.math += #div_1e4.d pool.math
