# pool:physics/events/take — @s's stored event is at the earliest time #te of the moving balls' events
# (of balls tied at it, the last one visited is taken).
# Reads: @s pool.nt pool.nk pool.nr pool.np. Writes: #te #kind #event_rail #partner pool.tmp, tag
# pool.event (on @s only).
scoreboard players operation #te pool.tmp = @s pool.nt
scoreboard players operation #kind pool.tmp = @s pool.nk
scoreboard players operation #event_rail pool.tmp = @s pool.nr
scoreboard players operation #partner pool.tmp = @s pool.np
tag @e[tag=pool.event] remove pool.event
tag @s add pool.event
