# a bee nest saves its bees (BeehiveBlockEntity, 1.20.5+), a furnace its times before 1.21.4
setblock ~ ~ ~ minecraft:bee_nest
execute store result score #bees machines.read run data get block ~ ~ ~ bees
assert score #bees machines.read matches 0
assert data block ~ ~ ~ {id:"minecraft:beehive"}
setblock ~ ~ ~ minecraft:furnace
assert data block ~ ~ ~ {BurnTime:0s,CookTimeTotal:0s,RecipesUsed:{}}
setblock ~ ~ ~ minecraft:oak_wall_sign
assert data block ~ ~ ~ {id:"minecraft:sign"}
# a block without a block entity ignores the NBT it is placed with (BlockInput.place)
setblock ~ ~ ~ minecraft:stone{BurnTime:5s}
execute store success score #entity machines.read run data get block ~ ~ ~
assert score #entity machines.read matches 0
