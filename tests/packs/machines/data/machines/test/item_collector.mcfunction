# an item collector: dropped items over a hopper are taken in and passed down a hopper chain into a
# double chest (HopperBlockEntity.suckInItems, ejectItems; ChestBlock.getContainer: right half first)
setblock ~1 ~0 ~1 minecraft:chest[facing=north,type=left]
setblock ~2 ~0 ~1 minecraft:chest[facing=north,type=right]
setblock ~1 ~1 ~1 minecraft:hopper
setblock ~1 ~2 ~1 minecraft:hopper
summon minecraft:item ~1.5 ~3.1 ~1.5 {NoGravity:1b,Item:{id:"minecraft:emerald",count:3}}
await items block ~2 ~0 ~1 container.0 minecraft:emerald[count=3]
assert not entity @e[type=minecraft:item,distance=..4]
assert not items block ~1 ~0 ~1 container.* *
