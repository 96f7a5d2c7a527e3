# pool:physics/detect/rail_event — the rail crossing of @s is its earliest event so far.
# Reads: #t #pocket #rail pool.tmp. Writes: #best #kind #event_rail pool.tmp.
scoreboard players operation #best pool.tmp = #t pool.tmp
scoreboard players set #kind pool.tmp 2
execute if score #pocket pool.tmp matches 1 run scoreboard players set #kind pool.tmp 3
scoreboard players operation #event_rail pool.tmp = #rail pool.tmp
