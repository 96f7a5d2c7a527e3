# @dummy ~ ~ ~
summon interaction ~1.5 ~ ~.5 {Tags: ["clicks.button"], width: 1.0f, height: 2.0f}
dummy @s use entity @e[tag=clicks.button,limit=1]
# the dummy's use does not pass the game's network handler: the trigger is granted by hand, as packs test it
assert not entity @e[tag=clicks.button,tag=clicks.used]
assert data entity @e[tag=clicks.button,limit=1] interaction
advancement grant @s only clicks:right_click
assert entity @e[tag=clicks.button,tag=clicks.used]
# the reward forgot the use: no target any more
assert not data entity @e[tag=clicks.button,limit=1] interaction
execute as @e[tag=clicks.button] on target run scoreboard players set #target clicks.n 1
assert not score #target clicks.n matches 1
