# as a body of the pivot's segment
execute if score @s phys.key < #pivot phys.tmp run scoreboard players add #below phys.tmp 1
execute if score @s phys.key < #pivot phys.tmp run scoreboard players operation @s phys.seg = #lo phys.seg
execute if score @s phys.key >= #pivot phys.tmp run scoreboard players operation @s phys.seg = #hi phys.seg
