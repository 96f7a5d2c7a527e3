# pool:physics/resolve/ball_ball/store_b — take ball b's (@s) contact position and new velocity back
# and start its new phase. Reads: #ball_ball.b.x #ball_ball.b.z #ball_ball.b.vx #ball_ball.b.vz
# pool.tmp. Writes: @s scores.
scoreboard players operation @s pool.x = #ball_ball.b.x pool.tmp
scoreboard players operation @s pool.z = #ball_ball.b.z pool.tmp
scoreboard players operation @s pool.vx = #ball_ball.b.vx pool.tmp
scoreboard players operation @s pool.vz = #ball_ball.b.vz pool.tmp
function pool:physics/motion/start
