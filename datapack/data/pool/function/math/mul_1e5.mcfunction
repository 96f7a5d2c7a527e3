# pool:math/mul_1e5 — $out = round($a * $b / 100000), halves away from zero, without overflow.
# Reads: $a $b pool.math with |$a| <= 21000000 and |$b| <= 100000 (a length times a direction
# component x 100000). Writes: $out pool.math; temporaries #a #b #q #r #neg pool.math.
# a = h*1000 + l: a*b/1e5 = (h b)/100 + ((h b mod 100)*1000 + l b)/1e5, all below 2^31; when
# |a| <= 21474 the product itself fits (mul_1e5/small), as for most speeds.
execute if score $a pool.math matches -21474..21474 run return run function pool:math/mul_1e5/small
scoreboard players operation #a pool.math = $a pool.math
scoreboard players operation #b pool.math = $b pool.math
scoreboard players set #neg pool.math 0
execute if score #a pool.math matches ..-1 run scoreboard players add #neg pool.math 1
execute if score #a pool.math matches ..-1 run scoreboard players operation #a pool.math *= #-1 pool.const
execute if score #b pool.math matches ..-1 run scoreboard players add #neg pool.math 1
execute if score #b pool.math matches ..-1 run scoreboard players operation #b pool.math *= #-1 pool.const
scoreboard players operation #q pool.math = #a pool.math
scoreboard players operation #q pool.math /= #1000 pool.const
scoreboard players operation #q pool.math *= #b pool.math
scoreboard players operation #r pool.math = #a pool.math
scoreboard players operation #r pool.math %= #1000 pool.const
scoreboard players operation #r pool.math *= #b pool.math
scoreboard players operation #a pool.math = #q pool.math
scoreboard players operation #a pool.math %= #100 pool.const
scoreboard players operation #a pool.math *= #1000 pool.const
scoreboard players operation #r pool.math += #a pool.math
scoreboard players add #r pool.math 50000
scoreboard players operation #r pool.math /= #100000 pool.const
scoreboard players operation #q pool.math /= #100 pool.const
scoreboard players operation #q pool.math += #r pool.math
execute if score #neg pool.math matches 1 run scoreboard players operation #q pool.math *= #-1 pool.const
scoreboard players operation $out pool.math = #q pool.math
