# pool:physics/motion/roll/advance — roll @s for #motion.f pool.tmp (1/10000 tick) with deceleration
# mu_r g, stopping when the speed reaches 0. Position = start + direction x distance (no drift).
# Reads: #motion.f pool.tmp; @s pool.spd pool.s pool.dx pool.dz pool.x0 pool.z0.
# Writes: @s pool.spd pool.s pool.x pool.z pool.vx pool.vz pool.wx pool.wz (pool.state on stop);
# temporaries #roll.fs #roll.g #roll.r pool.tmp and the math library's.
execute if score #motion.f pool.tmp matches 10000 if score @s pool.spd >= $roll_tick_min pool.const run return run function pool:physics/motion/roll/whole_tick
# time to stop: spd * 10000 / 24525 = (spd / 24525) * 10000 + (spd mod 24525) * 10000 / 24525
scoreboard players operation #roll.fs pool.tmp = @s pool.spd
scoreboard players operation #roll.fs pool.tmp /= $mu_r_g pool.const
scoreboard players operation #roll.fs pool.tmp *= #10000 pool.const
scoreboard players operation #roll.r pool.tmp = @s pool.spd
scoreboard players operation #roll.r pool.tmp %= $mu_r_g pool.const
scoreboard players operation #roll.r pool.tmp *= #10000 pool.const
scoreboard players operation #roll.r pool.tmp /= $mu_r_g pool.const
scoreboard players operation #roll.fs pool.tmp += #roll.r pool.tmp
scoreboard players operation #motion.f pool.tmp < #roll.fs pool.tmp
# s += spd f / 10000 - mu_r_g g / 20000, g = f^2 / 10000
scoreboard players operation $a pool.math = @s pool.spd
scoreboard players operation $b pool.math = #motion.f pool.tmp
function pool:math/mul_unit
scoreboard players operation @s pool.s += $out pool.math
scoreboard players operation #roll.g pool.tmp = #motion.f pool.tmp
scoreboard players operation #roll.g pool.tmp *= #motion.f pool.tmp
scoreboard players operation #roll.g pool.tmp /= #10000 pool.const
scoreboard players operation $a pool.math = #roll.g pool.tmp
scoreboard players operation $a pool.math *= $mu_r_g pool.const
scoreboard players operation $b pool.math = #20000 pool.const
function pool:math/div_round
scoreboard players operation @s pool.s -= $out pool.math
# spd -= mu_r_g f / 10000
scoreboard players operation $a pool.math = #motion.f pool.tmp
scoreboard players operation $a pool.math *= $mu_r_g pool.const
scoreboard players operation $b pool.math = #10000 pool.const
function pool:math/div_round
scoreboard players operation @s pool.spd -= $out pool.math
function pool:physics/motion/roll/place
execute if score #motion.f pool.tmp = #roll.fs pool.tmp run function pool:physics/motion/roll/stop
