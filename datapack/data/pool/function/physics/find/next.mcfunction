# pool:physics/find/next — pool:physics/find/ball for the moving ball @s, then tag pool.found
# (done in this sub-step), when the search fits in this game tick's $budget: it starts only with
# room for its own work and one exact sweep, and is dropped (#abort, redone next game tick) when
# an exact sweep would pass #find_cap = $budget - 300. A search started early in a game tick
# (#work <= 1000) is never dropped, so that every game tick gets on.
# Reads: #work pool.tmp. Writes: tag pool.found; #c #find_cap #abort pool.tmp; through
# pool:physics/find/ball.
scoreboard players operation #c pool.tmp = #work pool.tmp
scoreboard players add #c pool.tmp 450
execute if score #c pool.tmp > $budget pool.const run return 0
scoreboard players operation #find_cap pool.tmp = $budget pool.const
scoreboard players remove #find_cap pool.tmp 300
execute if score #work pool.tmp matches ..1000 run scoreboard players set #find_cap pool.tmp 2147483647
scoreboard players set #abort pool.tmp 0
function pool:physics/find/ball
execute if score #abort pool.tmp matches 0 run tag @s add pool.found
