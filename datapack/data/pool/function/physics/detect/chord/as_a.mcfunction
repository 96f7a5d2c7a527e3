# pool:physics/detect/chord/as_a — @s's chord from #events.now to the tick's end into #sweep.a.bx
# #sweep.a.bz #sweep.a.ex #sweep.a.ez.
# Reads: @s chord scores, #events.now pool.tmp. Writes: @s chord start (moved to #events.now),
# #sweep.a.* pool.tmp.
function pool:physics/detect/chord/start
scoreboard players operation #sweep.a.bx pool.tmp = @s pool.cx
scoreboard players operation #sweep.a.bz pool.tmp = @s pool.cz
scoreboard players operation #sweep.a.ex pool.tmp = @s pool.x
scoreboard players operation #sweep.a.ez pool.tmp = @s pool.z
