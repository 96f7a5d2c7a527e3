tag @s add phys.pivot
scoreboard players operation #cur phys.seg = @s phys.seg
scoreboard players operation #base phys.tmp = @s phys.base
scoreboard players operation #pivot phys.tmp = @s phys.key
