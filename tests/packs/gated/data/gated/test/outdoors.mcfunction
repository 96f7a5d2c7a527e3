# sky light 15 reaches the test's block through air and the barrier ceiling (BarrierBlock passes
# sky light), not through a stone roof (BlockAndTintGetter.canSeeSky)
execute if predicate gated:outdoors run scoreboard players set #sky gated.hp 1
assert score #sky gated.hp matches 1
setblock ~ ~3 ~ minecraft:glass
assert predicate gated:outdoors
setblock ~ ~4 ~ minecraft:stone
execute unless predicate gated:outdoors run scoreboard players set #sky gated.hp 2
assert score #sky gated.hp matches 2
