# @dummy ~ ~ ~
advancement grant @s through rewards:child
assert entity @s[advancements={rewards:root=true,rewards:child=true,rewards:grandchild=true}]
advancement revoke @s from rewards:child
assert entity @s[advancements={rewards:root=true,rewards:child=false,rewards:grandchild=false}]
execute store result score #n rewards.chain run advancement grant @s until rewards:grandchild
assert score #n rewards.chain matches 2
execute store success score #ok rewards.chain run advancement grant @s only rewards:root
assert score #ok rewards.chain matches 0
