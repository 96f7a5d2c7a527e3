# pool:physics/motion/slide/whole_tick — pool:physics/motion/slide/advance for a whole tick
# (#motion.f = 10000, at most @s pool.tau): its formulas with f = 10000, the same integers (v f /
# 10000 = v, a f^2 / 20000 rounds as a / 2, (5/2) a f / 10000 as 5 a / 2): r += v + a/2, v += a, w
# -= 5a/2, tau -= 10000.
# Reads/writes: as pool:physics/motion/slide/advance.
scoreboard players operation $a pool.math = @s pool.ax
scoreboard players operation $b pool.math = #2 pool.const
function pool:math/div_round
scoreboard players operation @s pool.x += @s pool.vx
scoreboard players operation @s pool.x += $out pool.math
scoreboard players operation $a pool.math *= #5 pool.const
function pool:math/div_round
scoreboard players operation @s pool.wx -= $out pool.math
scoreboard players operation @s pool.vx += @s pool.ax
scoreboard players operation $a pool.math = @s pool.az
function pool:math/div_round
scoreboard players operation @s pool.z += @s pool.vz
scoreboard players operation @s pool.z += $out pool.math
scoreboard players operation $a pool.math *= #5 pool.const
function pool:math/div_round
scoreboard players operation @s pool.wz -= $out pool.math
scoreboard players operation @s pool.vz += @s pool.az
scoreboard players remove @s pool.tau 10000
