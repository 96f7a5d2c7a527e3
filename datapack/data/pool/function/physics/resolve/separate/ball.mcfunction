# pool:physics/resolve/separate/ball — ball @s (a) against every other ball in play after it (moving with
# a larger pool.id, or at rest): pairs closer than 2R + 10 um are pushed apart.
# Reads: @s pool.id pool.x pool.z. Writes: #a.id #a.x #a.z #sep_far #sep_act pool.tmp, tag
# pool.self (removed).
scoreboard players set #sep_far pool.tmp 204261264
scoreboard players set #sep_act pool.tmp 1
scoreboard players operation #a.id pool.tmp = @s pool.id
scoreboard players operation #a.x pool.tmp = @s pool.x
scoreboard players operation #a.z pool.tmp = @s pool.z
tag @s add pool.self
execute as @e[tag=pool.ball,tag=!pool.self,scores={pool.state=1..2}] if score @s pool.id > #a.id pool.tmp run function pool:physics/resolve/separate/pair
execute as @e[tag=pool.ball,tag=!pool.self,scores={pool.state=0}] run function pool:physics/resolve/separate/pair
tag @s remove pool.self
