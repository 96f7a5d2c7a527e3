# pool:physics/resolve/separate/passes — passes over the balls that the last pass pushed
# (pool.shifted becomes pool.again), four at most (#separate.passes), each ball admitted within the
# budget (pool:physics/resolve/separate/next_again); sets $carry pool.game when a pass is left
# unfinished.
# Reads/writes: #separate.passes pool.tmp, tags pool.shifted pool.again.
execute unless entity @e[tag=pool.again] if entity @e[tag=pool.shifted] if score #separate.passes pool.tmp matches ..3 run function pool:physics/resolve/separate/pushed
execute as @e[tag=pool.again] run function pool:physics/resolve/separate/next_again
execute if entity @e[tag=pool.again] run return run scoreboard players set $carry pool.game 1
execute if entity @e[tag=pool.shifted] if score #separate.passes pool.tmp matches ..3 run function pool:physics/resolve/separate/passes
