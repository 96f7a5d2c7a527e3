# pool:physics/detect/chord/box — the box around @s's chord, from its start (cx, cz) to its end (x,
# z) at the tick's end, grown by R: two balls whose boxes do not overlap cannot touch.
# Reads: @s pool.cx pool.cz pool.x pool.z. Writes: @s pool.lx pool.hx pool.lz pool.hz.
scoreboard players operation @s pool.lx = @s pool.cx
scoreboard players operation @s pool.lx < @s pool.x
scoreboard players operation @s pool.lx -= $R pool.const
scoreboard players operation @s pool.hx = @s pool.cx
scoreboard players operation @s pool.hx > @s pool.x
scoreboard players operation @s pool.hx += $R pool.const
scoreboard players operation @s pool.lz = @s pool.cz
scoreboard players operation @s pool.lz < @s pool.z
scoreboard players operation @s pool.lz -= $R pool.const
scoreboard players operation @s pool.hz = @s pool.cz
scoreboard players operation @s pool.hz > @s pool.z
scoreboard players operation @s pool.hz += $R pool.const
