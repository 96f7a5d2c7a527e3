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
# thrown from 0.7 east of the centre, 0.15625 lower, with no pickup delay; it has since moved one
# tick through the air (ItemEntity.tick: it moved by its motion, less 0.04 of gravity in y, then
# the motion was scaled by 0.98F, 0.98 in y), so where it came from is Pos - Motion / 0.98
assert entity @e[type=item,distance=..4,nbt={PickupDelay:0s,OnGround:0b}]
scoreboard objectives add crafting.spawn dummy
execute as @e[type=item,distance=..4] store result score #x crafting.spawn run data get entity @s Pos[0] 1000000
execute as @e[type=item,distance=..4] store result score #mx crafting.spawn run data get entity @s Motion[0] 1000000
execute as @e[type=item,distance=..4] store result score #y crafting.spawn run data get entity @s Pos[1] 1000000
execute as @e[type=item,distance=..4] store result score #my crafting.spawn run data get entity @s Motion[1] 1000000
execute as @e[type=item,distance=..4] store result score #z crafting.spawn run data get entity @s Pos[2] 1000000
execute as @e[type=item,distance=..4] store result score #mz crafting.spawn run data get entity @s Motion[2] 1000000
scoreboard players set #50 crafting.spawn 50
scoreboard players set #49 crafting.spawn 49
scoreboard players operation #mx crafting.spawn *= #50 crafting.spawn
scoreboard players operation #mx crafting.spawn /= #49 crafting.spawn
scoreboard players operation #x crafting.spawn -= #mx crafting.spawn
scoreboard players operation #my crafting.spawn *= #50 crafting.spawn
scoreboard players operation #my crafting.spawn /= #49 crafting.spawn
scoreboard players operation #y crafting.spawn -= #my crafting.spawn
scoreboard players operation #mz crafting.spawn *= #50 crafting.spawn
scoreboard players operation #mz crafting.spawn /= #49 crafting.spawn
scoreboard players operation #z crafting.spawn -= #mz crafting.spawn
assert score #x crafting.spawn matches 2199900..2200100
assert score #y crafting.spawn matches 1343650..1343850
assert score #z crafting.spawn matches 499900..500100
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
