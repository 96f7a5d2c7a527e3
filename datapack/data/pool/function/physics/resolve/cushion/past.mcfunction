# pool:physics/resolve/cushion/past — how far @s is past the rail line n . r = off (#cushion.p, um,
# > 0 outside) and how fast it moves out (#cushion.vo = -v . n, um/tick), n the inward normal.
# Reads: #cushion.nx #cushion.nz #cushion.off pool.tmp, @s pool.x pool.z pool.vx pool.vz. Writes:
# #cushion.p #cushion.vo #cushion.d pool.tmp.
scoreboard players operation #cushion.p pool.tmp = @s pool.x
scoreboard players operation #cushion.p pool.tmp *= #cushion.nx pool.tmp
scoreboard players operation #cushion.d pool.tmp = @s pool.z
scoreboard players operation #cushion.d pool.tmp *= #cushion.nz pool.tmp
scoreboard players operation #cushion.p pool.tmp += #cushion.d pool.tmp
scoreboard players operation #cushion.p pool.tmp *= #-1 pool.const
scoreboard players operation #cushion.p pool.tmp += #cushion.off pool.tmp
scoreboard players operation #cushion.vo pool.tmp = @s pool.vx
scoreboard players operation #cushion.vo pool.tmp *= #cushion.nx pool.tmp
scoreboard players operation #cushion.d pool.tmp = @s pool.vz
scoreboard players operation #cushion.d pool.tmp *= #cushion.nz pool.tmp
scoreboard players operation #cushion.vo pool.tmp += #cushion.d pool.tmp
scoreboard players operation #cushion.vo pool.tmp *= #-1 pool.const
