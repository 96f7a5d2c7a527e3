# pool:physics/resolve/ball_ball/load_b — copy ball b (@s) into #ball_ball.b.* for
# pool:physics/resolve/ball_ball/collide.
# Reads: @s pool.x pool.z pool.vx pool.vz. Writes: #ball_ball.b.x #ball_ball.b.z #ball_ball.b.vx
# #ball_ball.b.vz pool.tmp.
scoreboard players operation #ball_ball.b.x pool.tmp = @s pool.x
scoreboard players operation #ball_ball.b.z pool.tmp = @s pool.z
scoreboard players operation #ball_ball.b.vx pool.tmp = @s pool.vx
scoreboard players operation #ball_ball.b.vz pool.tmp = @s pool.vz
