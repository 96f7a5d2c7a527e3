# An arrow shot across the test sticks in the barrier wall round it, 0.05 short of the face
summon arrow ~0.5 ~0.5 ~0.5 {Motion:[0.3d,0.0d,0.0d],NoGravity:1b,Tags:["shot"]}
await entity @e[tag=shot,nbt={inGround:1b}]
execute positioned ~0.95 ~0.5 ~0.5 run assert entity @e[tag=shot,distance=..0.001]
await delay 5
assert entity @e[tag=shot,nbt={inGround:1b,life:5s}]
