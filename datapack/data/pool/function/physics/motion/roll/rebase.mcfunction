# pool:physics/motion/roll/rebase — move the start of @s's rolling line to where the ball is (x0 += d
# round(s/100), z0 likewise), s keeping what is left: pool.s (0.01 um) would pass 2^31 after
# 21.47 m of one rolling phase, and pool:physics/motion/roll/place multiplies at most 21 m. Run
# when the state is saved (pool:physics/events/save), so that every rewind restores an s measured
# from the start it is used with; the position it gives is the same integer.
# Reads/writes: @s pool.s pool.x0 pool.z0; reads pool.dx pool.dz. Writes: #roll.l pool.tmp and
# the math library's temporaries.
scoreboard players operation $a pool.math = @s pool.s
scoreboard players operation $b pool.math = #100 pool.const
function pool:math/div_round
scoreboard players operation #roll.l pool.tmp = $out pool.math
scoreboard players operation $a pool.math = $out pool.math
scoreboard players operation $b pool.math = @s pool.dx
function pool:math/mul_1e5
scoreboard players operation @s pool.x0 += $out pool.math
scoreboard players operation $b pool.math = @s pool.dz
function pool:math/mul_1e5
scoreboard players operation @s pool.z0 += $out pool.math
scoreboard players operation #roll.l pool.tmp *= #100 pool.const
scoreboard players operation @s pool.s -= #roll.l pool.tmp
