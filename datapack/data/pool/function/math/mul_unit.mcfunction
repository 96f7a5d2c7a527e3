# pool:math/mul_unit — $out = round($a * $b / 10000) without overflow, rounding half away from 0.
# Reads: $a $b pool.math with |$b| <= 214748 and |$a * $b| < 2.1e13 (e.g. um times a unit vector
# component x 10000). Writes: $out pool.math; temporaries #mul_unit.a #mul_unit.b #mul_unit.q
# #mul_unit.r #mul_unit.neg pool.math.
# Works on magnitudes so that mirrored inputs give exactly mirrored outputs.
# a*b/c = (a div c)*b + ((a mod c)*b)/c keeps every intermediate inside int32; when |b| <= 10000
# (a unit vector component) and |a| <= 214700 the product is formed directly (mul_unit/small).
execute if score $b pool.math matches -10000..10000 if score $a pool.math matches -214700..214700 run return run function pool:math/mul_unit/small
scoreboard players operation #mul_unit.a pool.math = $a pool.math
scoreboard players operation #mul_unit.b pool.math = $b pool.math
scoreboard players set #mul_unit.neg pool.math 0
execute if score #mul_unit.a pool.math matches ..-1 run scoreboard players add #mul_unit.neg pool.math 1
execute if score #mul_unit.a pool.math matches ..-1 run scoreboard players operation #mul_unit.a pool.math *= #-1 pool.const
execute if score #mul_unit.b pool.math matches ..-1 run scoreboard players add #mul_unit.neg pool.math 1
execute if score #mul_unit.b pool.math matches ..-1 run scoreboard players operation #mul_unit.b pool.math *= #-1 pool.const
scoreboard players operation #mul_unit.q pool.math = #mul_unit.a pool.math
scoreboard players operation #mul_unit.q pool.math /= #10000 pool.const
scoreboard players operation #mul_unit.q pool.math *= #mul_unit.b pool.math
scoreboard players operation #mul_unit.r pool.math = #mul_unit.a pool.math
scoreboard players operation #mul_unit.r pool.math %= #10000 pool.const
scoreboard players operation #mul_unit.r pool.math *= #mul_unit.b pool.math
scoreboard players add #mul_unit.r pool.math 5000
scoreboard players operation #mul_unit.r pool.math /= #10000 pool.const
scoreboard players operation #mul_unit.q pool.math += #mul_unit.r pool.math
execute if score #mul_unit.neg pool.math matches 1 run scoreboard players operation #mul_unit.q pool.math *= #-1 pool.const
scoreboard players operation $out pool.math = #mul_unit.q pool.math
