# a crafter facing east, its slots in any 2x2 corner: the mirrored pattern matches too
setblock ~1 ~ ~ minecraft:crafter[orientation=east_up]
item replace block ~1 ~ ~ container.4 with minecraft:gold_ingot 2
item replace block ~1 ~ ~ container.8 with minecraft:stick 3
# placing it beside power does not trigger it: a neighbour must change
setblock ~1 ~1 ~ minecraft:redstone_block
await block ~1 ~ ~ minecraft:crafter[triggered=true]
assert block ~1 ~ ~ minecraft:crafter[crafting=false]
await entity @e[type=item,distance=..4]
assert block ~1 ~ ~ minecraft:crafter[crafting=true]
assert entity @e[type=item,distance=..4,nbt={Item:{id:"minecraft:stick",count:1,components:{"minecraft:custom_data":{wand:1b}}}}]
# thrown from 0.7 east of the centre, 0.15625 lower, with no pickup delay
assert entity @e[type=item,x=2.2,y=1.34375,z=0.5,distance=..0.0001,nbt={PickupDelay:0s}]
assert items block ~1 ~ ~ container.4 minecraft:gold_ingot[count=1]
assert items block ~1 ~ ~ container.8 minecraft:stick[count=2]
await block ~1 ~ ~ minecraft:crafter[crafting=false]
# the power stays on: no second craft until it is pulsed again
await delay 10
assert items block ~1 ~ ~ container.8 minecraft:stick[count=2]
setblock ~1 ~1 ~ air
assert block ~1 ~ ~ minecraft:crafter[triggered=false]
setblock ~1 ~1 ~ minecraft:redstone_block
await items block ~1 ~ ~ container.8 minecraft:stick[count=1]
# what the crafter saves (CrafterBlockEntity.saveAdditional)
setblock ~1 ~2 ~ minecraft:crafter
assert data block ~1 ~2 ~ {crafting_ticks_remaining:0,triggered:0,Items:[]}
