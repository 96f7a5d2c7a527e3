# at midnight the open sky gives 15 less 11; a torch two blocks away gives its 14 less one a step
# (BlockLightEngine.propagateIncrease), and the predicate reads the larger (getMaxLocalRawBrightness)
time set 18000
await delay 1t
assert not predicate gated:lamplit
setblock ~2 ~ ~ minecraft:torch
assert predicate gated:lamplit
setblock ~1 ~ ~ minecraft:stone
execute unless predicate gated:lamplit run scoreboard players set #lamp gated.hp 1
assert score #lamp gated.hp matches 1
setblock ~1 ~ ~ minecraft:air
setblock ~2 ~ ~ minecraft:air
assert not predicate gated:lamplit
