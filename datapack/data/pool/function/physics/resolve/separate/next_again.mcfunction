# pool:physics/resolve/separate/next_again — pool:physics/resolve/separate/again for the pushed ball @s, when about
# 450 more commands fit in this game tick's $budget (or nothing else ran yet).
# Reads/writes: #work #c pool.tmp; tag pool.again (removed when done).
scoreboard players operation #c pool.tmp = #work pool.tmp
scoreboard players add #c pool.tmp 450
execute if score #work pool.tmp matches 1.. if score #c pool.tmp > $budget pool.const run return 0
scoreboard players operation #work pool.tmp = #c pool.tmp
tag @s remove pool.again
function pool:physics/resolve/separate/again
