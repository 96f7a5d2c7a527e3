# pool:physics/resolve/separate/next_again — pool:physics/resolve/separate/again for the pushed ball
# @s, when about 450 more commands fit in this game tick's $budget (or nothing else ran yet).
# Reads/writes: #cost.work #cost.next pool.tmp; tag pool.again (removed when done).
scoreboard players operation #cost.next pool.tmp = #cost.work pool.tmp
scoreboard players add #cost.next pool.tmp 450
execute if score #cost.work pool.tmp matches 1.. if score #cost.next pool.tmp > $budget pool.const run return 0
scoreboard players operation #cost.work pool.tmp = #cost.next pool.tmp
tag @s remove pool.again
function pool:physics/resolve/separate/again
