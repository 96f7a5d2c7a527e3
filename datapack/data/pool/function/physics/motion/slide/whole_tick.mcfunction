# pool:physics/motion/slide/whole_tick — pool:physics/motion/slide/advance for a whole tick
# (#motion.f = 10000, at most @s pool.tau): its formulas with f = 10000, the same integers (dv = a,
# the move fvx + a in 1/2000 um): r += v + a/2, v += a, w -= 5a/2, tau -= 10000.
# Reads/writes: as pool:physics/motion/slide/advance.
scoreboard players operation @s pool.px += @s pool.fvx
scoreboard players operation @s pool.px += @s pool.ax
scoreboard players operation @s pool.fvx += @s pool.ax
scoreboard players operation @s pool.fvx += @s pool.ax
scoreboard players operation #slide.dv pool.tmp = @s pool.ax
scoreboard players operation #slide.dv pool.tmp *= #5 pool.const
scoreboard players operation @s pool.fwx -= #slide.dv pool.tmp
scoreboard players operation @s pool.pz += @s pool.fvz
scoreboard players operation @s pool.pz += @s pool.az
scoreboard players operation @s pool.fvz += @s pool.az
scoreboard players operation @s pool.fvz += @s pool.az
scoreboard players operation #slide.dv pool.tmp = @s pool.az
scoreboard players operation #slide.dv pool.tmp *= #5 pool.const
scoreboard players operation @s pool.fwz -= #slide.dv pool.tmp
function pool:physics/motion/slide/integers
scoreboard players remove @s pool.tau 10000
