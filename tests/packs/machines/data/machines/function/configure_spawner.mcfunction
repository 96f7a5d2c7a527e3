# a custom spawner: placed empty, then its next spawn and delays merged in
setblock ~ ~ ~ minecraft:spawner
data merge block ~ ~ ~ {SpawnData:{entity:{id:"minecraft:zombie",Tags:["machines.spawned"]}},MinSpawnDelay:40s,MaxSpawnDelay:40s}
