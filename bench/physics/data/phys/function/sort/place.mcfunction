# as the pivot: its rank is final; the display shows it
scoreboard players operation @s phys.rank = #base phys.tmp
scoreboard players operation @s phys.rank += #below phys.tmp
execute store result entity @s transformation.translation[0] float 0.1 run scoreboard players get @s phys.rank
tag @s remove phys.pivot
tag @s remove phys.sort
