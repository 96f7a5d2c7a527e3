# pool:physics/find/rail_event — the rail crossing of @s is the earliest event so far.
# Reads: #rf #pocket #rail pool.tmp. Writes: #best #kind #event_rail pool.tmp, tags.
scoreboard players operation #best pool.tmp = #rf pool.tmp
scoreboard players set #kind pool.tmp 2
execute if score #pocket pool.tmp matches 1 run scoreboard players set #kind pool.tmp 3
scoreboard players operation #event_rail pool.tmp = #rail pool.tmp
tag @e[tag=pool.event] remove pool.event
tag @e[tag=pool.event_b] remove pool.event_b
tag @s add pool.event
