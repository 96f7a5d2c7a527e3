# pool:physics/motion/roll/whole_tick — pool:physics/motion/roll/advance for a whole tick (#motion.f
# = 10000) of a ball too fast to stop within it (spd >= $roll_tick_min): its formulas with f =
# 10000, the same integers.
# Reads/writes: as pool:physics/motion/roll/advance.
scoreboard players operation @s pool.s += @s pool.spd
scoreboard players operation @s pool.s -= $mu_r_g_half pool.const
scoreboard players operation @s pool.spd -= $mu_r_g pool.const
function pool:physics/motion/roll/place
