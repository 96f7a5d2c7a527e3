# An arrow left stuck in the air falls (nothing within 0.06 of it) and sticks in the block below:
# the structure block under the test's corner
summon arrow ~0.5 ~0.5 ~0.5 {inGround:1b,Tags:["dropped"]}
await entity @e[tag=dropped,nbt={inGround:0b}]
await entity @e[tag=dropped,nbt={inGround:1b}]
execute positioned ~0.5 ~0.05 ~0.5 run assert entity @e[tag=dropped,distance=..0.001]
