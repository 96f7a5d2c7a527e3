# @dummy ~0.5 ~ ~0.5
fill ~-1 ~-1 ~-1 ~1 ~1 ~1 minecraft:air replace minecraft:barrier
summon interaction ~0.5 ~ ~-1.5 {Tags: ["sight.target"], width: 1.0f, height: 2.0f}
summon interaction ~1.5 ~ ~0.5 {Tags: ["sight.target"], width: 0.5f, height: 2.0f}
# facing south, the dummy sees nothing
assert not predicate sight:looking_at_target
# facing east: the narrow interaction a block away
tp @s ~0.5 ~ ~0.5 -90 0
assert predicate sight:looking_at_target
# facing north: the wide one
tp @s ~0.5 ~ ~0.5 180 0
assert predicate sight:looking_at_target
tag @e[type=interaction] remove sight.target
assert not predicate sight:looking_at_target
assert predicate {condition: "entity_properties", entity: "this", predicate: {"type_specific/player": {looking_at: {entity_tags: {none_of: ["sight.target"]}}}}}
