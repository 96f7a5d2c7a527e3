# pool:physics/events/take — @s's stored event is at the earliest time #events.te of the moving
# balls' events (of balls tied at it, the last one visited is taken).
# Reads: @s pool.nt pool.nk pool.nr pool.np. Writes: #events.te #events.kind #events.rail
# #events.partner pool.tmp, tag pool.event (on @s only).
scoreboard players operation #events.te pool.tmp = @s pool.nt
scoreboard players operation #events.kind pool.tmp = @s pool.nk
scoreboard players operation #events.rail pool.tmp = @s pool.nr
scoreboard players operation #events.partner pool.tmp = @s pool.np
tag @e[tag=pool.event] remove pool.event
tag @s add pool.event
