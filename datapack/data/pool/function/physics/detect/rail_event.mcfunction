# pool:physics/detect/rail_event — the rail crossing of @s is its earliest event so far.
# Reads: #detect.t #sweep.pocket #sweep.rail pool.tmp. Writes: #detect.best #detect.kind
# #detect.rail pool.tmp.
scoreboard players operation #detect.best pool.tmp = #detect.t pool.tmp
scoreboard players set #detect.kind pool.tmp 2
execute if score #sweep.pocket pool.tmp matches 1 run scoreboard players set #detect.kind pool.tmp 3
scoreboard players operation #detect.rail pool.tmp = #sweep.rail pool.tmp
