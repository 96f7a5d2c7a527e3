setblock ~ ~ ~ gravel
assert block ~ ~ ~ #gated:soft
setblock ~ ~ ~ stone
assert not block ~ ~ ~ #gated:soft
setblock ~1 ~ ~ sand
summon marker ~1.5 ~1 ~0.5 {Tags:["m"]}
assert entity @e[tag=m,predicate=gated:on_soft_ground]
