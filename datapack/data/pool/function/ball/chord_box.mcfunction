# pool:ball/chord_box — the box around @s's chord of this sub-step (from the saved start to the
# current end), grown by R: two balls whose boxes do not overlap cannot touch.
# Reads: @s pool.bx pool.bz pool.x pool.z. Writes: @s pool.lx pool.hx pool.lz pool.hz.
scoreboard players operation @s pool.lx = @s pool.bx
scoreboard players operation @s pool.lx < @s pool.x
scoreboard players operation @s pool.lx -= $R pool.const
scoreboard players operation @s pool.hx = @s pool.bx
scoreboard players operation @s pool.hx > @s pool.x
scoreboard players operation @s pool.hx += $R pool.const
scoreboard players operation @s pool.lz = @s pool.bz
scoreboard players operation @s pool.lz < @s pool.z
scoreboard players operation @s pool.lz -= $R pool.const
scoreboard players operation @s pool.hz = @s pool.bz
scoreboard players operation @s pool.hz > @s pool.z
scoreboard players operation @s pool.hz += $R pool.const
