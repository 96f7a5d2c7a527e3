# pool:physics/events/restore/slide — the sliding @s's fine state back from its saved objectives
# (pool:physics/events/save/slide). Reads: @s pool.bpx pool.bpz pool.bfvx pool.bfvz pool.bfwx
# pool.bfwz. Writes: @s pool.px pool.pz pool.fvx pool.fvz pool.fwx pool.fwz.
scoreboard players operation @s pool.px = @s pool.bpx
scoreboard players operation @s pool.pz = @s pool.bpz
scoreboard players operation @s pool.fvx = @s pool.bfvx
scoreboard players operation @s pool.fvz = @s pool.bfvz
scoreboard players operation @s pool.fwx = @s pool.bfwx
scoreboard players operation @s pool.fwz = @s pool.bfwz
