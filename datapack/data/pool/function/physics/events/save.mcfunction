# pool:physics/events/save — copy @s's changing state into the saved objectives (pool.b*), at time
# #events.now.
# Reads: #events.now pool.tmp, @s pool.x pool.z pool.vx pool.vz pool.wx pool.wz pool.wy pool.tau
# pool.s pool.spd pool.state (a sliding ball's fine state too: pool:physics/events/save/slide).
# Writes: @s pool.bx ... pool.bstate, pool.bt (the time).
# The phase constants (ax az rx rz dx dz x0 z0) change only when a phase starts, which
# pool:physics/motion/advance redoes identically after a restore; a rolling phase past 10 m moves
# its start up to the ball first (pool:physics/motion/roll/rebase: pool.s must stay below 2^31).
execute if score @s pool.state matches 2 if score @s pool.s matches 1000000000.. run function pool:physics/motion/roll/rebase
scoreboard players operation @s pool.bx = @s pool.x
scoreboard players operation @s pool.bz = @s pool.z
scoreboard players operation @s pool.bvx = @s pool.vx
scoreboard players operation @s pool.bvz = @s pool.vz
scoreboard players operation @s pool.bwx = @s pool.wx
scoreboard players operation @s pool.bwz = @s pool.wz
scoreboard players operation @s pool.bwy = @s pool.wy
scoreboard players operation @s pool.btau = @s pool.tau
scoreboard players operation @s pool.bs = @s pool.s
scoreboard players operation @s pool.bspd = @s pool.spd
scoreboard players operation @s pool.bstate = @s pool.state
scoreboard players operation @s pool.bt = #events.now pool.tmp
execute if score @s pool.state matches 1 run function pool:physics/events/save/slide
