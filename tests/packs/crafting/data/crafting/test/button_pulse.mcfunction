# @dummy ~ ~ ~
# a dummy presses a stone button on the crafter's side: the crafter crafts once; the button springs
# back after 20 ticks and the crafter is no longer triggered
setblock ~2 ~ ~ minecraft:crafter[orientation=up_north]
item replace block ~2 ~ ~ container.0 with minecraft:gold_ingot 2
item replace block ~2 ~ ~ container.4 with minecraft:blaze_rod 2
setblock ~2 ~ ~-1 minecraft:stone_button[face=wall,facing=north]
dummy @s use block ~2 ~ ~-1
assert block ~2 ~ ~ minecraft:crafter[triggered=true]
await entity @e[type=item,nbt={Item:{id:"minecraft:stick"}}]
assert items block ~2 ~ ~ container.0 minecraft:gold_ingot[count=1]
await block ~2 ~ ~ minecraft:crafter[triggered=false]
assert block ~2 ~ ~-1 minecraft:stone_button[powered=false]
assert items block ~2 ~ ~ container.4 minecraft:blaze_rod[count=1]
