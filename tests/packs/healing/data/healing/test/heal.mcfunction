# @dummy ~ ~ ~
# @skyaccess
# a new player takes no damage for 60 ticks (ServerPlayer.spawnInvulnerableTime); no barrier ceiling
# over its eyes (it would suffocate in it)
await delay 60
damage @s 10
assert entity @s[nbt={Health:10f}]
function healing:heal
# the effect waits for the player's tick; so does the reward
assert entity @s[nbt={Health:10f}]
assert not score @s healing.heals matches 1..
await entity @s[nbt={Health:20f}]
assert score @s healing.heals matches 1
assert not entity @s[nbt={active_effects: [{}]}]
