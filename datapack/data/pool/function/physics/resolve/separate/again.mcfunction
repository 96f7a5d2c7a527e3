# pool:physics/resolve/separate/again — ball @s (a), moved by a push, against every other ball in
# play: pairs that overlap (closer than 2R) are pushed to 2R + 10 um apart (a push can carry a ball
# into a third one; pairs a few um short of 2R + 10 are left as they are, so that pushes do not
# ripple through a cluster of touching balls).
# Reads: @s pool.id pool.x pool.z. Writes: #separate.a.id #separate.a.x #separate.a.z #separate.far
# #separate.act pool.tmp, tag pool.self (removed).
scoreboard players set #separate.far pool.tmp 204204100
scoreboard players set #separate.act pool.tmp 11
scoreboard players operation #separate.a.id pool.tmp = @s pool.id
scoreboard players operation #separate.a.x pool.tmp = @s pool.x
scoreboard players operation #separate.a.z pool.tmp = @s pool.z
tag @s add pool.self
execute as @e[tag=pool.ball,tag=!pool.self,scores={pool.state=0..2}] run function pool:physics/resolve/separate/pair
tag @s remove pool.self
