# @dummy ~ ~ ~
summon armor_stand ~ ~ ~ {Tags: ["giver"]}
# given by an armor stand: the source condition fails; too weak: the effects condition fails
execute as @e[tag=giver] run effect give @p minecraft:slowness 10 1
effect clear @s minecraft:slowness
effect give @s minecraft:slowness 10 0
assert not score @s healing.given matches 1..
# given by the player itself, strong enough
effect give @s minecraft:slowness 10 2
assert score @s healing.given matches 1
# a removal has no source
effect clear @s
assert score @s healing.given matches 1
