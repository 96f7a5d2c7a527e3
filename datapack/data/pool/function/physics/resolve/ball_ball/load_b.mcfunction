# pool:physics/resolve/ball_ball/load_b — copy ball b (@s) into #b.* for pool:physics/resolve/ball_ball/collide.
# Reads: @s pool.x pool.z pool.vx pool.vz. Writes: #b.x #b.z #b.vx #b.vz pool.tmp.
scoreboard players operation #b.x pool.tmp = @s pool.x
scoreboard players operation #b.z pool.tmp = @s pool.z
scoreboard players operation #b.vx pool.tmp = @s pool.vx
scoreboard players operation #b.vz pool.tmp = @s pool.vz
