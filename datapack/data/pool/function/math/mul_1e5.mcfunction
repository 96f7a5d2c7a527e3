# pool:math/mul_1e5 — $out = round($a * $b / 100000), halves away from zero, without overflow.
# Reads: $a $b pool.math with |$a| <= 21000000 and |$b| <= 100000 (a length times a direction
# component x 100000). Writes: $out pool.math; temporaries #mul_1e5.a #mul_1e5.b #mul_1e5.q
# #mul_1e5.r #mul_1e5.neg pool.math.
# a = h*1000 + l: a*b/1e5 = (h b)/100 + ((h b mod 100)*1000 + l b)/1e5, all below 2^31; when
# |a| <= 21474 the product itself fits (mul_1e5/small), as for most speeds.
execute if score $a pool.math matches -21474..21474 run return run function pool:math/mul_1e5/small
scoreboard players operation #mul_1e5.a pool.math = $a pool.math
scoreboard players operation #mul_1e5.b pool.math = $b pool.math
scoreboard players set #mul_1e5.neg pool.math 0
execute if score #mul_1e5.a pool.math matches ..-1 run scoreboard players add #mul_1e5.neg pool.math 1
execute if score #mul_1e5.a pool.math matches ..-1 run scoreboard players operation #mul_1e5.a pool.math *= #-1 pool.const
execute if score #mul_1e5.b pool.math matches ..-1 run scoreboard players add #mul_1e5.neg pool.math 1
execute if score #mul_1e5.b pool.math matches ..-1 run scoreboard players operation #mul_1e5.b pool.math *= #-1 pool.const
scoreboard players operation #mul_1e5.q pool.math = #mul_1e5.a pool.math
scoreboard players operation #mul_1e5.q pool.math /= #1000 pool.const
scoreboard players operation #mul_1e5.q pool.math *= #mul_1e5.b pool.math
scoreboard players operation #mul_1e5.r pool.math = #mul_1e5.a pool.math
scoreboard players operation #mul_1e5.r pool.math %= #1000 pool.const
scoreboard players operation #mul_1e5.r pool.math *= #mul_1e5.b pool.math
scoreboard players operation #mul_1e5.a pool.math = #mul_1e5.q pool.math
scoreboard players operation #mul_1e5.a pool.math %= #100 pool.const
scoreboard players operation #mul_1e5.a pool.math *= #1000 pool.const
scoreboard players operation #mul_1e5.r pool.math += #mul_1e5.a pool.math
scoreboard players add #mul_1e5.r pool.math 50000
scoreboard players operation #mul_1e5.r pool.math /= #100000 pool.const
scoreboard players operation #mul_1e5.q pool.math /= #100 pool.const
scoreboard players operation #mul_1e5.q pool.math += #mul_1e5.r pool.math
execute if score #mul_1e5.neg pool.math matches 1 run scoreboard players operation #mul_1e5.q pool.math *= #-1 pool.const
scoreboard players operation $out pool.math = #mul_1e5.q pool.math
