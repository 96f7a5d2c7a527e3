# pool:physics/detect/store — keep the earliest event found for @s, unless the search was dropped
# (#abort: pool:physics/detect/pair ran out of this game tick's budget; it is redone next tick).
# Reads: #abort #best #kind #event_rail #partner pool.tmp. Writes: @s pool.nt pool.nk pool.nr
# pool.np, tag pool.stale removed.
execute if score #abort pool.tmp matches 1 run return 0
tag @s remove pool.stale
scoreboard players operation @s pool.nt = #best pool.tmp
scoreboard players operation @s pool.nk = #kind pool.tmp
scoreboard players operation @s pool.nr = #event_rail pool.tmp
scoreboard players operation @s pool.np = #partner pool.tmp
