# pool:physics/resolve/cushion — @s reached rail #events.rail: put its centre on the rail line
# (the chord found the crossing; the curved path may differ by < 1 mm) and rebound.
# Reads: #events.rail pool.tmp. Writes: @s scores; #cushion.nx #cushion.nz pool.tmp.
scoreboard players set #cushion.nx pool.tmp 0
scoreboard players set #cushion.nz pool.tmp 0
execute if score #events.rail pool.tmp matches 1 run scoreboard players set #cushion.nx pool.tmp 1
execute if score #events.rail pool.tmp matches 1 run scoreboard players operation @s pool.x = $R pool.const
execute if score #events.rail pool.tmp matches 2 run scoreboard players set #cushion.nx pool.tmp -1
execute if score #events.rail pool.tmp matches 2 run scoreboard players operation @s pool.x = $L pool.const
execute if score #events.rail pool.tmp matches 2 run scoreboard players operation @s pool.x -= $R pool.const
execute if score #events.rail pool.tmp matches 3 run scoreboard players set #cushion.nz pool.tmp 1
execute if score #events.rail pool.tmp matches 3 run scoreboard players operation @s pool.z = $R pool.const
execute if score #events.rail pool.tmp matches 4 run scoreboard players set #cushion.nz pool.tmp -1
execute if score #events.rail pool.tmp matches 4 run scoreboard players operation @s pool.z = $W pool.const
execute if score #events.rail pool.tmp matches 4 run scoreboard players operation @s pool.z -= $R pool.const
function pool:physics/resolve/cushion/rebound
