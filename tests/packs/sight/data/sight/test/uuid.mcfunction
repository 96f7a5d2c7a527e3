# @dummy ~0.5 ~ ~0.5
summon item_display ~ ~ ~ {Tags: ["sight.holder"]}
summon pig ~ ~ ~ {Tags: ["sight.pig"], NoAI: 1b, UUID: [I; 1, 2, 3, 4]}
execute as @n[tag=sight.pig] run function sight:uuid_of
assert data storage sight:out {uuid: "00000001-0000-0002-0000-000300000004"}
execute if entity 00000001-0000-0002-0000-000300000004
assert entity @n[tag=sight.holder,nbt={item: {components: {"minecraft:custom_name": {hover_event: {action: "show_entity", id: "minecraft:pig"}}}}}]
