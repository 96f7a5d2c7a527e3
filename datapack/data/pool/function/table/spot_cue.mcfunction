# pool:table/spot_cue — put a pocketed cue ball back on the head spot (L/4, W/2), at rest, when
# the table rests and no ball lies within 2R of the spot.
# Reads: $resting pool.game, the balls' pool.x pool.z. Writes: the cue ball's scores and display;
# temporaries #spot_cue.d #spot_cue.n pool.tmp.
execute if score $resting pool.game matches 0 run return fail
scoreboard players set #spot_cue.n pool.tmp 0
execute as @e[tag=pool.ball,scores={pool.state=0..2}] run function pool:table/spot_cue/check
execute if score #spot_cue.n pool.tmp matches 1.. run tellraw @a {"text":"Pool: the head spot is taken","color":"red"}
execute if score #spot_cue.n pool.tmp matches 1.. run return fail
execute as @e[tag=pool.ball,scores={pool.id=0,pool.state=3},limit=1] run function pool:table/spot_cue/place
