# @dummy ~ ~ ~
# LootCommand.playerGive does not broadcast: the change is seen in the player's next tick
# (ServerPlayer.tick: containerMenu.broadcastChanges)
loot give @s loot rewards:diamonds
assert entity @s[advancements={rewards:got_diamond=false}]
await entity @s[advancements={rewards:got_diamond=true}]
assert score @s rewards.got matches 1
