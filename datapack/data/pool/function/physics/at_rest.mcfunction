# pool:physics/at_rest — no ball moves any more: the table is at rest and a new shot may be played.
# Writes: $resting pool.game (1).
scoreboard players set $resting pool.game 1
tellraw @a {"text":"Pool: the table is at rest"}
