# pool:physics/events/restore — copy the saved objectives (pool.b*) back into @s's state.
# Reads: @s pool.bx pool.bz pool.bvx pool.bvz pool.bwx pool.bwz pool.bwy pool.btau pool.bs pool.bspd
# pool.bstate (a sliding ball's fine state too: pool:physics/events/restore/slide). Writes: @s pool.x pool.z pool.vx pool.vz pool.wx pool.wz pool.wy pool.tau pool.s
# pool.spd pool.state.
scoreboard players operation @s pool.x = @s pool.bx
scoreboard players operation @s pool.z = @s pool.bz
scoreboard players operation @s pool.vx = @s pool.bvx
scoreboard players operation @s pool.vz = @s pool.bvz
scoreboard players operation @s pool.wx = @s pool.bwx
scoreboard players operation @s pool.wz = @s pool.bwz
scoreboard players operation @s pool.wy = @s pool.bwy
scoreboard players operation @s pool.tau = @s pool.btau
scoreboard players operation @s pool.s = @s pool.bs
scoreboard players operation @s pool.spd = @s pool.bspd
scoreboard players operation @s pool.state = @s pool.bstate
execute if score @s pool.state matches 1 run function pool:physics/events/restore/slide
