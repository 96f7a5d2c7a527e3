# pool:physics/detect/mark_stale — after an event, the balls whose stored event involved one of its
# balls must look again (pool.stale); the event's balls themselves get new chords.
# Reads: the event tags, pool.id, pool.nk pool.np. Writes: tag pool.stale; #detect.id pool.tmp.
execute as @e[tag=pool.event] run scoreboard players operation #detect.id pool.tmp = @s pool.id
execute as @e[tag=pool.moving,scores={pool.nk=1}] if score @s pool.np = #detect.id pool.tmp run tag @s add pool.stale
execute unless entity @e[tag=pool.event_b] run return 0
execute as @e[tag=pool.event_b] run scoreboard players operation #detect.id pool.tmp = @s pool.id
execute as @e[tag=pool.moving,scores={pool.nk=1}] if score @s pool.np = #detect.id pool.tmp run tag @s add pool.stale
