# pool:physics/resolve/separate/next_touch — pool:physics/resolve/separate/ball for the ball @s that touched another,
# when about 450 more commands fit in this game tick's $budget (or nothing else ran yet).
# Reads/writes: #work #c pool.tmp; tag pool.touch (removed when done).
scoreboard players operation #c pool.tmp = #work pool.tmp
scoreboard players add #c pool.tmp 450
execute if score #work pool.tmp matches 1.. if score #c pool.tmp > $budget pool.const run return 0
scoreboard players operation #work pool.tmp = #c pool.tmp
tag @s remove pool.touch
function pool:physics/resolve/separate/ball
