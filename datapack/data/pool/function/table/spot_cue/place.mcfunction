# pool:table/spot_cue/place — the cue ball @s returns to the head spot, at rest, its display back on the table.
# Writes: @s pool.x pool.z pool.state and motion scores, its display; tag pool.settled removed.
tag @s remove pool.settled
scoreboard players set @s pool.x 635000
scoreboard players set @s pool.z 635000
function pool:physics/motion/roll/stop
scoreboard players set @s pool.wy 0
function pool:physics/display/place
