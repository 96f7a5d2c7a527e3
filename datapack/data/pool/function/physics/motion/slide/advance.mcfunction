# pool:physics/motion/slide/advance — slide @s for #motion.f pool.tmp (1/10000 tick, at most @s
# pool.tau): r += v f + a f^2 / 2, v += a f, w -= (5/2) a f, tau -= f.
# Reads: #motion.f pool.tmp; @s pool.x pool.z pool.vx pool.vz pool.wx pool.wz pool.ax pool.az
# pool.tau.
# Writes: those @s scores; temporary #slide.g pool.tmp and the math library's.
execute if score #motion.f pool.tmp matches 10000 run return run function pool:physics/motion/slide/whole_tick
# g = f^2 / 10000 (so a f^2 / 2 = a g / 20000 in um)
scoreboard players operation #slide.g pool.tmp = #motion.f pool.tmp
scoreboard players operation #slide.g pool.tmp *= #motion.f pool.tmp
scoreboard players operation $a pool.math = #slide.g pool.tmp
scoreboard players operation $b pool.math = #10000 pool.const
function pool:math/div_round
scoreboard players operation #slide.g pool.tmp = $out pool.math
# x
scoreboard players operation $a pool.math = @s pool.vx
scoreboard players operation $b pool.math = #motion.f pool.tmp
function pool:math/mul_unit
scoreboard players operation @s pool.x += $out pool.math
scoreboard players operation $a pool.math = @s pool.ax
scoreboard players operation $a pool.math *= #slide.g pool.tmp
scoreboard players operation $b pool.math = #20000 pool.const
function pool:math/div_round
scoreboard players operation @s pool.x += $out pool.math
# z
scoreboard players operation $a pool.math = @s pool.vz
scoreboard players operation $b pool.math = #motion.f pool.tmp
function pool:math/mul_unit
scoreboard players operation @s pool.z += $out pool.math
scoreboard players operation $a pool.math = @s pool.az
scoreboard players operation $a pool.math *= #slide.g pool.tmp
scoreboard players operation $b pool.math = #20000 pool.const
function pool:math/div_round
scoreboard players operation @s pool.z += $out pool.math
# v and w
scoreboard players operation $a pool.math = @s pool.ax
scoreboard players operation $b pool.math = #motion.f pool.tmp
function pool:math/mul_unit
scoreboard players operation @s pool.vx += $out pool.math
scoreboard players operation $a pool.math *= #5 pool.const
function pool:math/mul_unit
scoreboard players operation $a pool.math = $out pool.math
scoreboard players operation $b pool.math = #2 pool.const
function pool:math/div_round
scoreboard players operation @s pool.wx -= $out pool.math
scoreboard players operation $a pool.math = @s pool.az
scoreboard players operation $b pool.math = #motion.f pool.tmp
function pool:math/mul_unit
scoreboard players operation @s pool.vz += $out pool.math
scoreboard players operation $a pool.math *= #5 pool.const
function pool:math/mul_unit
scoreboard players operation $a pool.math = $out pool.math
scoreboard players operation $b pool.math = #2 pool.const
function pool:math/div_round
scoreboard players operation @s pool.wz -= $out pool.math
scoreboard players operation @s pool.tau -= #motion.f pool.tmp
