# pool:math/mul_1e5/small — pool:math/mul_1e5 when |$a| <= 21474 and |$b| <= 100000, so that
# |a b| + 50000 fits in an int.
# Reads: $a $b pool.math. Writes: $out pool.math; temporary #mul_1e5.p pool.math.
scoreboard players operation #mul_1e5.p pool.math = $a pool.math
scoreboard players operation #mul_1e5.p pool.math *= $b pool.math
scoreboard players operation $out pool.math = #mul_1e5.p pool.math
execute if score #mul_1e5.p pool.math matches ..-1 run scoreboard players operation $out pool.math *= #-1 pool.const
scoreboard players add $out pool.math 50000
scoreboard players operation $out pool.math /= #100000 pool.const
execute if score #mul_1e5.p pool.math matches ..-1 run scoreboard players operation $out pool.math *= #-1 pool.const
