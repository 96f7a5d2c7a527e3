# pool:physics/events/at_rest — no ball moves any more: the table is at rest and a new shot may be
# played.
# Side spin left on a ball at rest (it spins in place) is cleared: at 779 um/tick^2 it would be
# gone within seconds, before the next shot, and the tick loop stops running.
# Writes: $resting pool.game (1), every ball's pool.wy (0).
scoreboard players set $resting pool.game 1
scoreboard players set @e[tag=pool.ball] pool.wy 0
tellraw @a {"text":"Pool: the table is at rest"}
