# @dummy ~ ~ ~
advancement grant @s only rewards:chain_a
assert score @s rewards.chain matches 11
assert entity @s[advancements={rewards:chain_a=true,rewards:chain_b=true}]
