# pool:physics/motion/slide/start — begin sliding (errata 2.x): constant slip direction u_hat,
# dv/dt = -mu_s g u_hat, duration tau = 2|u| / (7 mu_s g), then v = w = (5 v + 2 w) / 7.
# Reads: @s pool.vx pool.vz pool.wx pool.wz; $ux $uz $len pool.math (the slip's direction, size).
# Writes: @s pool.state (1) pool.ax pool.az (um/tick^2) pool.tau (1/10000 tick) pool.rx pool.rz.
scoreboard players set @s pool.state 1
scoreboard players operation $a pool.math = $mu_s_g pool.const
scoreboard players operation $a pool.math *= #-1 pool.const
scoreboard players operation $b pool.math = $ux pool.math
function pool:math/mul_unit
scoreboard players operation @s pool.ax = $out pool.math
scoreboard players operation $b pool.math = $uz pool.math
function pool:math/mul_unit
scoreboard players operation @s pool.az = $out pool.math
# tau = |u| * 20000 / (7 * 4905) = |u| * 4000 / 6867 in 1/10000 tick, as (q*4000) + (r*4000)/6867
scoreboard players set #slide.den pool.tmp 6867
scoreboard players set #slide.num pool.tmp 4000
scoreboard players operation @s pool.tau = $len pool.math
scoreboard players operation @s pool.tau /= #slide.den pool.tmp
scoreboard players operation @s pool.tau *= #slide.num pool.tmp
scoreboard players operation #slide.r pool.tmp = $len pool.math
scoreboard players operation #slide.r pool.tmp %= #slide.den pool.tmp
scoreboard players operation #slide.r pool.tmp *= #slide.num pool.tmp
scoreboard players operation #slide.r pool.tmp /= #slide.den pool.tmp
scoreboard players operation @s pool.tau += #slide.r pool.tmp
# rolling velocity v - (2/7)(v - w) = (5 v + 2 w) / 7
scoreboard players operation $a pool.math = @s pool.vx
scoreboard players operation $a pool.math *= #5 pool.const
scoreboard players operation #slide.r pool.tmp = @s pool.wx
scoreboard players operation #slide.r pool.tmp *= #2 pool.const
scoreboard players operation $a pool.math += #slide.r pool.tmp
scoreboard players operation $b pool.math = #7 pool.const
function pool:math/div_round
scoreboard players operation @s pool.rx = $out pool.math
scoreboard players operation $a pool.math = @s pool.vz
scoreboard players operation $a pool.math *= #5 pool.const
scoreboard players operation #slide.r pool.tmp = @s pool.wz
scoreboard players operation #slide.r pool.tmp *= #2 pool.const
scoreboard players operation $a pool.math += #slide.r pool.tmp
function pool:math/div_round
scoreboard players operation @s pool.rz = $out pool.math
