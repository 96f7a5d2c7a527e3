# the block runs the tag's functions each tick: a module sees a new marker on the next tick
scoreboard players operation #start ticker.n = #ticks ticker.n
summon marker ~ ~1 ~ {Tags: ["ticker.new"]}
await entity @e[type=marker,tag=ticker.seen,distance=..2]
await delay 3t
execute store result score #now ticker.n run scoreboard players get #ticks ticker.n
scoreboard players operation #now ticker.n -= #start ticker.n
# the block ran on the tick the marker was seen and on each of the three awaited
assert score #now ticker.n matches 4..5
# the block's source was told which functions it runs (a text component from 1.21.5)
assert data block 29999 0 29999 LastOutput.extra[{translate: "commands.function.scheduled.multiple"}]
assert data block 29999 0 29999 {SuccessCount: 0}
