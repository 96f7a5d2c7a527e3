# pool:math/mul_unit/small — pool:math/mul_unit when |$a| <= 214700 and |$b| <= 10000, so that
# |a b| + 5000 fits in an int.
# Reads: $a $b pool.math. Writes: $out pool.math; temporary #mul_unit.p pool.math.
scoreboard players operation #mul_unit.p pool.math = $a pool.math
scoreboard players operation #mul_unit.p pool.math *= $b pool.math
scoreboard players operation $out pool.math = #mul_unit.p pool.math
execute if score #mul_unit.p pool.math matches ..-1 run scoreboard players operation $out pool.math *= #-1 pool.const
scoreboard players add $out pool.math 5000
scoreboard players operation $out pool.math /= #10000 pool.const
execute if score #mul_unit.p pool.math matches ..-1 run scoreboard players operation $out pool.math *= #-1 pool.const
