# pool:math/div_1e4/digit — one decimal digit of pool:math/div_1e4's long division.
# Reads/writes: $out (quotient so far), #n (remainder) pool.math; temporary #d pool.math.
scoreboard players operation #n pool.math *= #10 pool.const
scoreboard players operation #d pool.math = #n pool.math
scoreboard players operation #d pool.math /= $b pool.math
scoreboard players operation #n pool.math %= $b pool.math
scoreboard players operation $out pool.math *= #10 pool.const
scoreboard players operation $out pool.math += #d pool.math
