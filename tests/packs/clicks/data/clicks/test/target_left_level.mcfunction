# @dummy ~ ~ ~
summon interaction ~1.5 ~ ~.5 {Tags: ["clicks.button"], width: 1.0f, height: 2.0f}
dummy @s use entity @e[tag=clicks.button,limit=1]
execute as @e[tag=clicks.button] on target run scoreboard players set #here clicks.n 1
assert score #here clicks.n matches 1
# Level.getPlayerByUUID looks in the interaction's own level only
execute in minecraft:the_nether run tp @s 0 100 0
execute as @e[tag=clicks.button] on target run scoreboard players set #nether clicks.n 1
assert not score #nether clicks.n matches 1
