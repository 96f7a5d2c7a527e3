# a new armor stand saves both hands and all armour slots, empty ({}) until set
assert entity @e[type=armor_stand,tag=toolstand,nbt={HandItems: [{}, {}], ArmorItems: [{}, {}, {}, {}]}]
data modify storage toolstand: tool set value {id: "minecraft:stick", Count: 1b, tag: {probe: 1b}}
function toolstand:drop_with
assert block 0 251 0 chest{Items: [{Slot: 0b, id: "minecraft:diamond"}]}
data modify storage toolstand: tool set value {id: "minecraft:stick", Count: 1b}
function toolstand:drop_with
assert block 0 251 0 chest{Items: [{Slot: 0b, id: "minecraft:cobblestone"}]}
