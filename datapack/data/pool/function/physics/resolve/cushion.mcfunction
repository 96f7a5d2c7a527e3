# pool:physics/resolve/cushion — @s reached rail #events.rail: it is moved to where its path crosses
# the rail line (pool:physics/resolve/cushion/cross: the chord's crossing, linear in time, put the
# ball up to 0.6 mm past the line and 0.5 mm along the rail from it), its centre put on the line,
# and it rebounds.
# Reads: #events.rail pool.tmp. Writes: @s scores; #cushion.nx #cushion.nz #cushion.off pool.tmp
# (the rail line is n . r = off); #events.te through cushion/cross.
scoreboard players set #cushion.nx pool.tmp 0
scoreboard players set #cushion.nz pool.tmp 0
scoreboard players operation #cushion.off pool.tmp = $R pool.const
execute if score #events.rail pool.tmp matches 1 run scoreboard players set #cushion.nx pool.tmp 1
execute if score #events.rail pool.tmp matches 2 run scoreboard players set #cushion.nx pool.tmp -1
execute if score #events.rail pool.tmp matches 2 run scoreboard players operation #cushion.off pool.tmp -= $L pool.const
execute if score #events.rail pool.tmp matches 3 run scoreboard players set #cushion.nz pool.tmp 1
execute if score #events.rail pool.tmp matches 4 run scoreboard players set #cushion.nz pool.tmp -1
execute if score #events.rail pool.tmp matches 4 run scoreboard players operation #cushion.off pool.tmp -= $W pool.const
function pool:physics/resolve/cushion/cross
execute if score #events.rail pool.tmp matches 1 run scoreboard players operation @s pool.x = $R pool.const
execute if score #events.rail pool.tmp matches 2 run scoreboard players operation @s pool.x = $L pool.const
execute if score #events.rail pool.tmp matches 2 run scoreboard players operation @s pool.x -= $R pool.const
execute if score #events.rail pool.tmp matches 3 run scoreboard players operation @s pool.z = $R pool.const
execute if score #events.rail pool.tmp matches 4 run scoreboard players operation @s pool.z = $W pool.const
execute if score #events.rail pool.tmp matches 4 run scoreboard players operation @s pool.z -= $R pool.const
function pool:physics/resolve/cushion/rebound
