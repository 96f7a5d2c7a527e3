# pool:physics/motion/start — start the motion phase that @s's velocity and spin call for:
# sliding while the slip u = v - w is at least 1 um/tick, else rolling, else at rest.
# Reads: @s pool.vx pool.vz pool.wx pool.wz pool.x pool.z.
# Writes: @s pool.state and that phase's scores (see pool:physics/motion/slide/start,
# pool:physics/motion/roll/start).
scoreboard players operation $x pool.math = @s pool.vx
scoreboard players operation $x pool.math -= @s pool.wx
scoreboard players operation $z pool.math = @s pool.vz
scoreboard players operation $z pool.math -= @s pool.wz
function pool:math/normalize
execute if score $len pool.math matches 1.. run return run function pool:physics/motion/slide/start
function pool:physics/motion/roll/start
