# @dummy
# @skyaccess
# inside the block, beside the dummy (at the block's corner Bob's eyes would be in the barrier wall;
# where the dummy stands a hurt's knockback would have no direction)
execute positioned ~0.25 ~ ~0.5 run dummy Bob spawn
# a new player takes no damage for 60 ticks (ServerPlayer.spawnInvulnerableTime)
await delay 60
team join squads.red @s
team join squads.red Bob
assert entity @s[team=squads.red]
assert entity @a[name=Bob,team=squads.red]
execute store result score #red squads.n run team list squads.red
assert score #red squads.n matches 2
# a teammate's hit does nothing without friendly fire
damage Bob 4 minecraft:player_attack by @s
assert entity @a[name=Bob,nbt={Health: 20.0f}]
team join squads.blue Bob
damage Bob 4 minecraft:player_attack by @s
assert entity @a[name=Bob,nbt={Health: 16.0f}]
assert not entity @a[name=Bob,team=squads.red]
dummy Bob leave
