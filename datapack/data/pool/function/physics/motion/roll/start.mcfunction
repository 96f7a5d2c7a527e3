# pool:physics/motion/roll/start — begin rolling along @s's velocity (w = v), or come to rest.
# Reads: @s pool.vx pool.vz pool.x pool.z. Writes: @s pool.state (2 rolling, 0 at rest),
# pool.spd (|v| in 0.01 um/tick), pool.dx pool.dz (v / |v| x 100000), pool.s (0), pool.x0 pool.z0,
# pool.wx pool.wz; temporaries #roll.l #roll.e pool.tmp and the math library's.
# The direction needs 1e-5 (1e-4 rad would put a ball 1 mm off after 10 m), so |v| is refined
# from normalize's unit vector u: |v| = (v . u) / |u| with |u| = 1 + e/2, e = |u|^2 - 1.
scoreboard players operation $x pool.math = @s pool.vx
scoreboard players operation $z pool.math = @s pool.vz
function pool:math/normalize
scoreboard players operation @s pool.wx = @s pool.vx
scoreboard players operation @s pool.wz = @s pool.vz
execute if score $len pool.math matches 0 run return run function pool:physics/motion/roll/stop
scoreboard players set @s pool.state 2
scoreboard players operation $a pool.math = @s pool.vx
scoreboard players operation $a pool.math *= #100 pool.const
scoreboard players operation $b pool.math = $ux pool.math
function pool:math/mul_unit
scoreboard players operation #roll.l pool.tmp = $out pool.math
scoreboard players operation $a pool.math = @s pool.vz
scoreboard players operation $a pool.math *= #100 pool.const
scoreboard players operation $b pool.math = $uz pool.math
function pool:math/mul_unit
scoreboard players operation #roll.l pool.tmp += $out pool.math
scoreboard players operation #roll.e pool.tmp = $ux pool.math
scoreboard players operation #roll.e pool.tmp *= $ux pool.math
scoreboard players operation $b pool.math = $uz pool.math
scoreboard players operation $b pool.math *= $uz pool.math
scoreboard players operation #roll.e pool.tmp += $b pool.math
scoreboard players operation #roll.e pool.tmp -= #100000000 pool.const
scoreboard players operation $a pool.math = #roll.l pool.tmp
scoreboard players operation $b pool.math = #roll.e pool.tmp
function pool:math/mul_unit
scoreboard players operation $a pool.math = $out pool.math
scoreboard players operation $b pool.math = #20000 pool.const
function pool:math/div_round
scoreboard players operation #roll.l pool.tmp -= $out pool.math
scoreboard players operation @s pool.spd = #roll.l pool.tmp
# direction d = 10^7 v / spd = 10000 (1000 v) / spd
scoreboard players operation $b pool.math = @s pool.spd
scoreboard players operation $a pool.math = @s pool.vx
scoreboard players operation $a pool.math *= #1000 pool.const
function pool:math/div_1e4
scoreboard players operation @s pool.dx = $out pool.math
scoreboard players operation $a pool.math = @s pool.vz
scoreboard players operation $a pool.math *= #1000 pool.const
function pool:math/div_1e4
scoreboard players operation @s pool.dz = $out pool.math
scoreboard players set @s pool.s 0
scoreboard players operation @s pool.x0 = @s pool.x
scoreboard players operation @s pool.z0 = @s pool.z
