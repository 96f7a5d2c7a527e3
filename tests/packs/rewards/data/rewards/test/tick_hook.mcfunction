# @dummy ~ ~ ~
await delay 5
assert score @s rewards.ticks matches 5
assert entity @s[advancements={rewards:tick_hook=false,rewards:creative_only=false}]
