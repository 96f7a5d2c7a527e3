# @dummy ~ ~ ~
setblock ~2 ~ ~ minecraft:crafter[orientation=up_north]
item replace block ~2 ~ ~ container.1 with minecraft:gold_ingot
item replace block ~2 ~ ~ container.3 with minecraft:stick
setblock ~2 ~ ~1 minecraft:redstone_block
await entity @e[type=item]
# a stick: the criterion's ingredient predicate wants a blaze rod
assert not score @s crafting.heard matches 1..
setblock ~2 ~ ~1 air
item replace block ~2 ~ ~ container.1 with minecraft:gold_ingot
item replace block ~2 ~ ~ container.3 with minecraft:blaze_rod
setblock ~2 ~ ~1 minecraft:redstone_block
await score @s crafting.heard matches 1
