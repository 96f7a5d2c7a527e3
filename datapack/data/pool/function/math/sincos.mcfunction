# pool:math/sincos — sine and cosine of an angle in centidegrees (any int).
# Reads: $a pool.math. Writes: $sin $cos pool.math (x 10000, error <= 1 unit);
# temporaries #sincos.q #sincos.r #sincos.x #sincos.t #sincos.p #sincos.s #sincos.c pool.math.
# Reduced to an octant 0..45 degrees, where truncated Taylor series (terms to x^7 and x^8,
# remainders below 4e-6) are evaluated by Horner's rule on x in 1/10000 radian.
scoreboard players operation #sincos.r pool.math = $a pool.math
scoreboard players set #sincos.q pool.math 36000
scoreboard players operation #sincos.r pool.math %= #sincos.q pool.math
scoreboard players operation #sincos.q pool.math = #sincos.r pool.math
scoreboard players set #sincos.t pool.math 9000
scoreboard players operation #sincos.q pool.math /= #sincos.t pool.math
scoreboard players operation #sincos.r pool.math %= #sincos.t pool.math
execute if score #sincos.r pool.math matches ..4500 run function pool:math/sincos/octant
execute if score #sincos.r pool.math matches 4501.. run function pool:math/sincos/octant_upper
# quadrant q: (sin, cos) of r + 90q degrees
execute if score #sincos.q pool.math matches 0 run scoreboard players operation $sin pool.math = #sincos.s pool.math
execute if score #sincos.q pool.math matches 0 run scoreboard players operation $cos pool.math = #sincos.c pool.math
execute if score #sincos.q pool.math matches 1 run scoreboard players operation $sin pool.math = #sincos.c pool.math
execute if score #sincos.q pool.math matches 1 run scoreboard players operation $cos pool.math = #sincos.s pool.math
execute if score #sincos.q pool.math matches 1 run scoreboard players operation $cos pool.math *= #-1 pool.const
execute if score #sincos.q pool.math matches 2 run scoreboard players operation $sin pool.math = #sincos.s pool.math
execute if score #sincos.q pool.math matches 2 run scoreboard players operation $sin pool.math *= #-1 pool.const
execute if score #sincos.q pool.math matches 2 run scoreboard players operation $cos pool.math = #sincos.c pool.math
execute if score #sincos.q pool.math matches 2 run scoreboard players operation $cos pool.math *= #-1 pool.const
execute if score #sincos.q pool.math matches 3 run scoreboard players operation $sin pool.math = #sincos.c pool.math
execute if score #sincos.q pool.math matches 3 run scoreboard players operation $sin pool.math *= #-1 pool.const
execute if score #sincos.q pool.math matches 3 run scoreboard players operation $cos pool.math = #sincos.s pool.math
