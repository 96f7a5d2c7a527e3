# pool:physics/resolve/separate/ball — ball @s (a) against every other ball in play after it (moving
# with a larger pool.id, or at rest): pairs closer than 2R + 10 um are pushed apart.
# Reads: @s pool.id pool.x pool.z. Writes: #separate.a.id #separate.a.x #separate.a.z #separate.far
# #separate.act pool.tmp, tag pool.self (removed).
scoreboard players set #separate.far pool.tmp 204261264
scoreboard players set #separate.act pool.tmp 1
scoreboard players operation #separate.a.id pool.tmp = @s pool.id
scoreboard players operation #separate.a.x pool.tmp = @s pool.x
scoreboard players operation #separate.a.z pool.tmp = @s pool.z
tag @s add pool.self
execute as @e[tag=pool.ball,tag=!pool.self,scores={pool.state=1..2}] if score @s pool.id > #separate.a.id pool.tmp run function pool:physics/resolve/separate/pair
execute as @e[tag=pool.ball,tag=!pool.self,scores={pool.state=0}] run function pool:physics/resolve/separate/pair
tag @s remove pool.self
