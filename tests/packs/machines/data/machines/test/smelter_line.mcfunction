# a smelting line as machine packs build one: a hopper feeds a blast furnace from above
# (AbstractFurnaceBlockEntity.getSlotsForFace), a hopper beside it feeds the fuel, a hopper under it
# takes the results into a chest; the pack's blasting recipe cooks in 40 ticks
setblock ~1 ~3 ~1 minecraft:hopper{Items:[{Slot:0b,id:"minecraft:iron_nugget",count:2}]}
setblock ~1 ~2 ~1 minecraft:blast_furnace
setblock ~2 ~2 ~1 minecraft:hopper[facing=west]{Items:[{Slot:0b,id:"minecraft:coal",count:1}]}
setblock ~1 ~1 ~1 minecraft:hopper
setblock ~1 ~0 ~1 minecraft:chest
await items block ~1 ~0 ~1 container.0 minecraft:iron_ingot[count=2,custom_data~{machines_recycled:"yes"}]
assert block ~1 ~2 ~1 minecraft:blast_furnace[lit=true]
assert data block ~1 ~2 ~1 {RecipesUsed:{"machines:ingot_from_scrap":2}}
