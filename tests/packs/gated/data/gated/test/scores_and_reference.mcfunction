summon husk ~ ~ ~ {Tags:["a"],NoAI:1b}
execute as @e[tag=a] run scoreboard players set @s gated.hp 5
assert entity @e[tag=a,predicate=gated:healthy]
tag @e[tag=a] add marked
assert not entity @e[tag=a,predicate=gated:healthy]
