# pool:physics/resolve/separate/shift — move @s by (#separate.sx, #separate.sz) um, its rolling line
# (x0, z0) with it.
# Reads: #separate.sx #separate.sz pool.tmp. Writes: @s pool.x pool.z pool.x0 pool.z0; tag
# pool.settled removed, tag pool.shifted (pool:physics/resolve/separate/pushed looks at it again).
tag @s remove pool.settled
tag @s add pool.shifted
scoreboard players operation @s pool.x += #separate.sx pool.tmp
scoreboard players operation @s pool.z += #separate.sz pool.tmp
scoreboard players operation @s pool.x0 += #separate.sx pool.tmp
scoreboard players operation @s pool.z0 += #separate.sz pool.tmp
