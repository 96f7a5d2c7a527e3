# @dummy
scoreboard players set @s craft.rank 12
loot give @s loot craft:reward
assert items entity @s container.* minecraft:diamond[count=3]
assert items entity @s container.* minecraft:gold_ingot[count=2]
scoreboard players set @s craft.rank 0
clear @s
loot give @s loot craft:reward
assert items entity @s hotbar.0 minecraft:emerald
assert not items entity @s container.* minecraft:gold_ingot
execute store result score @s craft.found run clear @s minecraft:emerald 0
assert score @s craft.found matches 1
