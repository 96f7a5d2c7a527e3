# pool:physics/detect/next — the event search of ball @s with a new chord or a stale event
# (pool:physics/detect/ball when it moves, pool:physics/detect/rest at rest), then tag pool.found
# (done in this sub-step), when the search fits in this game tick's $budget: it starts only with
# room for its own work and one exact sweep, and is dropped (#detect.abort, redone next game tick)
# when an exact sweep would pass #detect.cap = $budget - 300. A search started early in a game tick
# (#cost.work <= 1000) is never dropped, so that every game tick gets on.
# Reads: #cost.work pool.tmp. Writes: tag pool.found; #cost.next #detect.cap #detect.abort pool.tmp;
# through the search.
scoreboard players operation #cost.next pool.tmp = #cost.work pool.tmp
scoreboard players add #cost.next pool.tmp 450
execute if score #cost.next pool.tmp > $budget pool.const run return 0
scoreboard players operation #detect.cap pool.tmp = $budget pool.const
scoreboard players remove #detect.cap pool.tmp 300
execute if score #cost.work pool.tmp matches ..1000 run scoreboard players set #detect.cap pool.tmp 2147483647
scoreboard players set #detect.abort pool.tmp 0
execute if entity @s[tag=pool.moving] run function pool:physics/detect/ball
execute if entity @s[tag=!pool.moving,scores={pool.state=0}] run function pool:physics/detect/rest
execute if score #detect.abort pool.tmp matches 0 run tag @s add pool.found
