# pool:controls/tick — in-game controls: "/trigger pool.power set P" (P = 1..100 % of full power)
# strikes the cue ball along the player's view, level cue, centre hit.
# Reads: players' pool.power. Writes: pool.power (reset), via pool:controls/strike.
scoreboard players enable @a pool.power
execute as @a[scores={pool.power=1..}] run function pool:controls/strike
