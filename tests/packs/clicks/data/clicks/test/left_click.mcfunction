# @dummy ~ ~ ~
summon interaction ~1.5 ~ ~.5 {Tags: ["clicks.button"], width: 1.0f, height: 2.0f}
summon interaction ~-1.5 ~ ~.5 {Tags: ["clicks.other"], width: 1.0f, height: 2.0f}
# nothing attacked it yet: no attacker
execute as @e[tag=clicks.button] on attacker run scoreboard players set #any clicks.n 1
assert not score #any clicks.n matches 1
dummy @s attack @e[tag=clicks.button,limit=1]
assert score @s clicks.left matches 1
assert entity @e[tag=clicks.button,tag=clicks.hit]
# the advancement revoked itself: a second click is heard again
dummy @s attack @e[tag=clicks.button,limit=1]
assert score @s clicks.left matches 2
# an interaction without the tag fails the criterion's entity condition
dummy @s attack @e[tag=clicks.other,limit=1]
assert score @s clicks.left matches 2
execute as @e[tag=clicks.other] on attacker run scoreboard players set #other clicks.n 1
assert score #other clicks.n matches 1
