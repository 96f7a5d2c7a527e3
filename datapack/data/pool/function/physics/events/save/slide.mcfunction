# pool:physics/events/save/slide — the sliding @s's fine state (pool:physics/motion/slide/start)
# into its saved objectives. Reads: @s pool.px pool.pz pool.fvx pool.fvz pool.fwx pool.fwz.
# Writes: @s pool.bpx pool.bpz pool.bfvx pool.bfvz pool.bfwx pool.bfwz.
scoreboard players operation @s pool.bpx = @s pool.px
scoreboard players operation @s pool.bpz = @s pool.pz
scoreboard players operation @s pool.bfvx = @s pool.fvx
scoreboard players operation @s pool.bfvz = @s pool.fvz
scoreboard players operation @s pool.bfwx = @s pool.fwx
scoreboard players operation @s pool.bfwz = @s pool.fwz
