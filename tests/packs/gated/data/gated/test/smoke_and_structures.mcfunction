# a campfire's smoke rises through air up to 5 blocks (CampfireBlock.isSmokeyPos); the test
# server's world has no structures (GameTestServer: WorldOptions without generated structures)
setblock ~ ~ ~ minecraft:campfire[lit=true]
execute positioned ~ ~3 ~ if predicate gated:in_smoke run scoreboard players set #smoke gated.hp 1
assert score #smoke gated.hp matches 1
setblock ~ ~1 ~ minecraft:stone
setblock ~ ~2 ~ minecraft:stone
execute positioned ~ ~3 ~ unless predicate gated:in_smoke run scoreboard players set #smoke gated.hp 2
assert score #smoke gated.hp matches 2
assert not predicate gated:in_village
