# @dummy
setblock ~ ~ ~ minecraft:barrel
item replace block ~ ~ ~ container.0 with minecraft:iron_ingot
item replace block ~ ~ ~ container.1 with minecraft:gold_ingot 3
item replace block ~ ~ ~ container.2 with minecraft:stick
function craft:check
# the ingredients were used up and the sword went into the first empty slot (LootCommand.distributeToContainer)
assert items block ~ ~ ~ container.0 minecraft:iron_sword[minecraft:custom_data~{crafted:1b},damage=125]
assert items block ~ ~ ~ container.1 minecraft:gold_ingot[count=2]
assert not items block ~ ~ ~ container.2 *
assert data block ~ ~ ~ Items[{id:"minecraft:iron_sword"}].components."minecraft:lore"
function craft:check
assert not items block ~ ~ ~ container.* minecraft:iron_sword[count=2]
item replace entity @s weapon.mainhand from block ~ ~ ~ container.0
function craft:count_swords
assert score @s craft.found matches 1
assert entity @s[nbt={SelectedItem:{id:"minecraft:iron_sword"}}]
