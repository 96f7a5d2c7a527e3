# @dummy ~ ~ ~
damage @s 10
assert entity @s[nbt={Health:10f}]
function healing:heal
# the effect waits for the player's tick; so does the reward
assert entity @s[nbt={Health:10f}]
assert not score @s healing.heals matches 1..
await entity @s[nbt={Health:20f}]
assert score @s healing.heals matches 1
assert not entity @s[nbt={active_effects: [{}]}]
