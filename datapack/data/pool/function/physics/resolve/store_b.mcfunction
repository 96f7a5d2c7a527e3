# pool:physics/resolve/store_b — take ball b's (@s) new velocity back and start its new phase.
# Reads: #b.vx #b.vz pool.tmp. Writes: @s pool.vx pool.vz and its phase scores.
scoreboard players operation @s pool.vx = #b.vx pool.tmp
scoreboard players operation @s pool.vz = #b.vz pool.tmp
function pool:ball/phase/start
