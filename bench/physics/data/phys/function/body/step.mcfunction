# as and at one body: move along the heading, read the position back, turn at the walls,
# look for neighbours in a 7 x 5 x 7 volume, exchange energy with them, show it
tag @s add phys.self
tag @s remove phys.near
tp @s ^ ^ ^0.1
execute store result score @s phys.x run data get entity @s Pos[0] 1000
execute store result score @s phys.z run data get entity @s Pos[2] 1000
execute unless score @s phys.x matches -2000..24500 run function phys:body/turn
execute unless score @s phys.z matches -2000..24500 run function phys:body/turn
execute positioned ~-3 ~-2 ~-3 if entity @e[dx=6,dy=4,dz=6,tag=phys.body,tag=!phys.self] run tag @s add phys.near
execute if entity @s[tag=phys.near] run function phys:body/contact
scoreboard players add @s phys.age 1
scoreboard players operation @s phys.size = @s phys.energy
scoreboard players operation @s phys.size %= #8 phys.const
scoreboard players add @s phys.size 1
execute store result entity @s transformation.scale[0] float 0.125 run scoreboard players get @s phys.size
execute store result entity @s transformation.scale[1] float 0.125 run scoreboard players get @s phys.size
execute store result entity @s transformation.translation[1] float 0.01 run scoreboard players get @s phys.hits
tag @s remove phys.self
