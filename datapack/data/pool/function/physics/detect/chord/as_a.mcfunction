# pool:physics/detect/chord/as_a — @s's chord from #now to the tick's end into #a.bx #a.bz #a.ex #a.ez.
# Reads: @s chord scores, #now pool.tmp. Writes: @s chord start (moved to #now), #a.* pool.tmp.
function pool:physics/detect/chord/start
scoreboard players operation #a.bx pool.tmp = @s pool.cx
scoreboard players operation #a.bz pool.tmp = @s pool.cz
scoreboard players operation #a.ex pool.tmp = @s pool.x
scoreboard players operation #a.ez pool.tmp = @s pool.z
