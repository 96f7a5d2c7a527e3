# @dummy ~ ~ ~
# the result and the bucket left by the milk go into the chest in front
setblock ~1 ~ ~ minecraft:crafter[orientation=down_north]
setblock ~1 ~-1 ~ minecraft:chest
item replace block ~1 ~-1 ~ container.0 with minecraft:cake
item replace block ~1 ~ ~ container.0 with minecraft:sugar
item replace block ~1 ~ ~ container.5 with minecraft:milk_bucket
item replace block ~1 ~ ~ container.7 with minecraft:turtle_egg
setblock ~1 ~1 ~ minecraft:redstone_block
await items block ~1 ~-1 ~ container.1 minecraft:cake
assert items block ~1 ~-1 ~ container.2 minecraft:bucket
assert not items block ~1 ~ ~ container.* *
assert not entity @e[type=item]
