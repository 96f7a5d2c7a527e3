# pool:physics/motion/slide/advance — slide @s for #motion.f pool.tmp (1/10000 tick, at most @s
# pool.tau) on its fine state (pool:physics/motion/slide/start): with dv = a f (0.001 um/tick),
# r += (v + dv / 2) f, v += dv, w -= (5/2) dv, tau -= f, each in 1/2000 um or um/tick, and the
# integer position, velocity and spin follow (pool:physics/motion/slide/integers), so that
# nothing is rounded twice over the slide.
# Reads: #motion.f pool.tmp; @s pool.ax pool.az pool.tau and the fine state. Writes: those @s
# scores, pool.x pool.z pool.vx pool.vz pool.wx pool.wz; temporaries #slide.dv #slide.p #slide.q
# #slide.r pool.tmp and the math library's.
execute if score #motion.f pool.tmp matches 10000 run return run function pool:physics/motion/slide/whole_tick
# dv = a f / 10000 (|a| <= 4905000, f <= 10000: pool:math/mul_unit's general form); the move in
# 1/2000 um is (2000 v + 1000 dv) f / 10000 = (fvx + dv) f / 10000, |fvx + dv| below 2^31 as
# fvx itself (pool:physics/motion/slide/start)
scoreboard players operation $a pool.math = @s pool.ax
scoreboard players operation $b pool.math = #motion.f pool.tmp
function pool:math/mul_unit
scoreboard players operation #slide.dv pool.tmp = $out pool.math
scoreboard players operation $a pool.math = @s pool.fvx
scoreboard players operation $a pool.math += #slide.dv pool.tmp
function pool:math/mul_unit
scoreboard players operation @s pool.px += $out pool.math
scoreboard players operation @s pool.fvx += #slide.dv pool.tmp
scoreboard players operation @s pool.fvx += #slide.dv pool.tmp
scoreboard players operation #slide.dv pool.tmp *= #5 pool.const
scoreboard players operation @s pool.fwx -= #slide.dv pool.tmp
# z
scoreboard players operation $a pool.math = @s pool.az
scoreboard players operation $b pool.math = #motion.f pool.tmp
function pool:math/mul_unit
scoreboard players operation #slide.dv pool.tmp = $out pool.math
scoreboard players operation $a pool.math = @s pool.fvz
scoreboard players operation $a pool.math += #slide.dv pool.tmp
function pool:math/mul_unit
scoreboard players operation @s pool.pz += $out pool.math
scoreboard players operation @s pool.fvz += #slide.dv pool.tmp
scoreboard players operation @s pool.fvz += #slide.dv pool.tmp
scoreboard players operation #slide.dv pool.tmp *= #5 pool.const
scoreboard players operation @s pool.fwz -= #slide.dv pool.tmp
function pool:physics/motion/slide/integers
scoreboard players operation @s pool.tau -= #motion.f pool.tmp
