# @dummy
team join squads.red @s
tellraw @a {"selector": "@s"}
assert chat "^\\[R\\] Dummy"
# a name can join before its player does
team add squads.late
team join squads.late Carol
dummy Carol spawn
assert entity @a[name=Carol,team=squads.late]
execute store result score #left squads.n run team empty squads.late
assert score #left squads.n matches 1
assert entity @a[name=Carol,team=]
execute store result score #teams squads.n run team remove squads.late
assert score #teams squads.n matches 2
dummy Carol leave
