tag @s add phys.sort
scoreboard players set @s phys.seg 0
scoreboard players set @s phys.base 0
scoreboard players operation @s phys.key = @s phys.energy
scoreboard players operation @s phys.key *= #1000 phys.const
scoreboard players operation @s phys.key += @s phys.id
