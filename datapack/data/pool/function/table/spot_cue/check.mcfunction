# pool:table/spot_cue/check — count @s in #n when its centre is within 2R of the head spot
# (a box test is enough: the spot is free when no ball is within 2R in both x and z).
# Reads: @s pool.x pool.z. Writes: #n #d pool.tmp.
scoreboard players operation #d pool.tmp = @s pool.x
scoreboard players remove #d pool.tmp 635000
execute unless score #d pool.tmp matches -57150..57150 run return 0
scoreboard players operation #d pool.tmp = @s pool.z
scoreboard players remove #d pool.tmp 635000
execute if score #d pool.tmp matches -57150..57150 run scoreboard players add #n pool.tmp 1
