# Stores the executing entity's UUID string in storage sight:out uuid: its display name, resolved
# by a selector text in a loot table's set_name, carries the UUID as its insertion.
tag @s add sight.this
loot replace entity @n[tag=sight.holder] contents loot {pools: [{rolls: 1, entries: [{type: "item", name: "stone", functions: [{function: "set_name", entity: "this", name: {selector: "@n[tag=sight.this]"}}]}]}]}
data modify storage sight:out uuid set from entity @n[tag=sight.holder] item.components."minecraft:custom_name".insertion
tag @s remove sight.this
