# BaseSpawner.save: a new spawner's counts stay as saved, the merged fields replace theirs
function machines:configure_spawner
assert data block ~ ~ ~ {id:"minecraft:mob_spawner",Delay:20s,MinSpawnDelay:40s,SpawnCount:4s,RequiredPlayerRange:16s}
assert data block ~ ~ ~ SpawnData.entity{id:"minecraft:zombie"}
execute store result score #range machines.read run data get block ~ ~ ~ RequiredPlayerRange
assert score #range machines.read matches 16
