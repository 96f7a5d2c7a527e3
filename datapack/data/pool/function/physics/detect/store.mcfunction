# pool:physics/detect/store — keep the earliest event found for @s, unless the search was dropped
# (#detect.abort: pool:physics/detect/pair/contact ran out of this game tick's budget; it is redone
# next tick). The rail and the partner are kept whatever the kind: each is read only with its own.
# Reads: #detect.abort #detect.best #detect.kind #detect.rail #detect.partner pool.tmp. Writes: @s
# pool.nt pool.nk pool.nr pool.np, tag pool.stale removed.
execute if score #detect.abort pool.tmp matches 1 run return 0
tag @s remove pool.stale
scoreboard players operation @s pool.nt = #detect.best pool.tmp
scoreboard players operation @s pool.nk = #detect.kind pool.tmp
scoreboard players operation @s pool.nr = #detect.rail pool.tmp
scoreboard players operation @s pool.np = #detect.partner pool.tmp
