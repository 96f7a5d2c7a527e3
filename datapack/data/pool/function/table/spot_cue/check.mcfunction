# pool:table/spot_cue/check — count @s in #spot_cue.n when its centre is within 2R of the head spot
# (a box test is enough: the spot is free when no ball is within 2R in both x and z).
# Reads: @s pool.x pool.z. Writes: #spot_cue.n #spot_cue.d pool.tmp.
scoreboard players operation #spot_cue.d pool.tmp = @s pool.x
scoreboard players remove #spot_cue.d pool.tmp 635000
execute unless score #spot_cue.d pool.tmp matches -57150..57150 run return 0
scoreboard players operation #spot_cue.d pool.tmp = @s pool.z
scoreboard players remove #spot_cue.d pool.tmp 635000
execute if score #spot_cue.d pool.tmp matches -57150..57150 run scoreboard players add #spot_cue.n pool.tmp 1
