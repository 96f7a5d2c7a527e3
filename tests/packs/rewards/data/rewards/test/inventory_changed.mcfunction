# @dummy ~ ~ ~
# InventoryChangeTrigger: give broadcasts the changed slots at once (GiveCommand); one item
# predicate tests the changed stack, several must each match a stack of the inventory
give @s diamond 1
assert entity @s[advancements={rewards:got_diamond=false,rewards:kit=false}]
give @s stick
assert entity @s[advancements={rewards:got_diamond=false,rewards:kit=true}]
give @s diamond 1
assert entity @s[advancements={rewards:got_diamond=true}]
await score @s rewards.got matches 1
clear @s
assert entity @s[advancements={rewards:emptied=true}]
