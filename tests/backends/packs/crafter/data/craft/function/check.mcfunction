# Run at a barrel: a shaped "recipe" in slots 0-2 (two iron ingots over a stick) becomes a sword.
execute if items block ~ ~ ~ container.0 #craft:metals if items block ~ ~ ~ container.1 #craft:metals if items block ~ ~ ~ container.2 minecraft:stick run function craft:make_sword
