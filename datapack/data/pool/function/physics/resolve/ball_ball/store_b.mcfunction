# pool:physics/resolve/ball_ball/store_b — take ball b's (@s) contact position and new velocity back and
# start its new phase. Reads: #b.x #b.z #b.vx #b.vz pool.tmp. Writes: @s scores.
scoreboard players operation @s pool.x = #b.x pool.tmp
scoreboard players operation @s pool.z = #b.z pool.tmp
scoreboard players operation @s pool.vx = #b.vx pool.tmp
scoreboard players operation @s pool.vz = #b.vz pool.tmp
function pool:physics/motion/start
