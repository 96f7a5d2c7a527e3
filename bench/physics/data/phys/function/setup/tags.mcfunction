# as a body: a group of 8, a kind of 3, a layer of 4, the first 64 sortable, a few sleeping
scoreboard players operation @s phys.tmp = @s phys.id
scoreboard players operation @s phys.tmp %= #8 phys.const
execute if score @s phys.tmp matches 0 run tag @s add phys.g0
execute if score @s phys.tmp matches 1 run tag @s add phys.g1
execute if score @s phys.tmp matches 2 run tag @s add phys.g2
execute if score @s phys.tmp matches 3 run tag @s add phys.g3
execute if score @s phys.tmp matches 4 run tag @s add phys.g4
execute if score @s phys.tmp matches 5 run tag @s add phys.g5
execute if score @s phys.tmp matches 6 run tag @s add phys.g6
execute if score @s phys.tmp matches 7 run tag @s add phys.g7
scoreboard players operation @s phys.tmp = @s phys.id
scoreboard players operation @s phys.tmp %= #3 phys.const
execute if score @s phys.tmp matches 0 run tag @s add phys.k0
execute if score @s phys.tmp matches 1 run tag @s add phys.k1
execute if score @s phys.tmp matches 2 run tag @s add phys.k2
scoreboard players operation @s phys.tmp = @s phys.id
scoreboard players operation @s phys.tmp /= #4 phys.const
scoreboard players operation @s phys.tmp %= #4 phys.const
execute if score @s phys.tmp matches 0 run tag @s add phys.l0
execute if score @s phys.tmp matches 1 run tag @s add phys.l1
execute if score @s phys.tmp matches 2 run tag @s add phys.l2
execute if score @s phys.tmp matches 3 run tag @s add phys.l3
execute if score @s phys.id matches ..63 run tag @s add phys.sortable
execute if score @s phys.id matches 200..211 run tag @s add phys.sleep
tag @s[tag=phys.k0,tag=phys.l0] add phys.heavy
tag @s[tag=phys.k1,tag=!phys.l0] add phys.light
tag @s[tag=!phys.heavy,tag=!phys.light] add phys.plain
tag @s add phys.active
