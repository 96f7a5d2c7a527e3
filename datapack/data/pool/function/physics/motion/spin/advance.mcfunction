# pool:physics/motion/spin/advance — side spin decays toward 0 by (5/2) mu_sp g per tick (errata),
# for #motion.f, stopping at 0. Reads: #motion.f pool.tmp; @s pool.wy. Writes: @s pool.wy; temporary
# #spin.d pool.tmp.
execute if score @s pool.wy matches 0 run return 0
scoreboard players operation #spin.d pool.tmp = @s pool.wy
scoreboard players operation $a pool.math = #motion.f pool.tmp
scoreboard players operation $a pool.math *= $spin_decay pool.const
scoreboard players operation $b pool.math = #10000 pool.const
function pool:math/div_round
execute if score #spin.d pool.tmp matches 1.. run scoreboard players operation @s pool.wy -= $out pool.math
execute if score #spin.d pool.tmp matches ..-1 run scoreboard players operation @s pool.wy += $out pool.math
execute if score #spin.d pool.tmp matches 1.. if score @s pool.wy matches ..-1 run scoreboard players set @s pool.wy 0
execute if score #spin.d pool.tmp matches ..-1 if score @s pool.wy matches 1.. run scoreboard players set @s pool.wy 0
