# pool:physics/motion/slide/start — begin sliding (errata 2.x): constant slip direction u_hat,
# dv/dt = -mu_s g u_hat, duration tau = 2|u| / (7 mu_s g), then v = w = (5 v + 2 w) / 7.
# The slide runs on its own fine state (pool:physics/motion/slide/advance): the acceleration in
# 0.001 um/tick^2 along u_hat to 1e-7 (a rounded um/tick^2 per component was up to 1e-4 rad off the
# slip and bent a stun shot's path some um sideways within a few ticks), the velocity and the
# spin in 1/2000 um/tick (pool.fvx pool.fvz pool.fwx pool.fwz) and the position's part below a um
# in 1/2000 um (pool.px pool.pz), all starting from the integer state.
# Reads: @s pool.vx pool.vz pool.wx pool.wz; $x $z $len pool.math (the slip u = v - w and its
# length, from pool:math/normalize).
# Writes: @s pool.state (1) pool.ax pool.az (0.001 um/tick^2) pool.tau (1/10000 tick) pool.rx
# pool.rz pool.px pool.pz pool.fvx pool.fvz pool.fwx pool.fwz; temporaries #slide.den #slide.num
# #slide.r pool.tmp and the math library's.
scoreboard players set @s pool.state 1
# a = -mu_s g u / |u|: u / |u| to 1e-7 first (pool:math/div_1e4 of 1000 u: |1000 u| < 2^31 for
# |u| < 2.1e6 um/tick, 42 m/s), then times mu_s g in 0.001 um/tick^2 (|4905 x 10^7| < 2.1e13 for
# pool:math/mul_unit; |a| <= 4905000)
scoreboard players operation $b pool.math = $len pool.math
scoreboard players operation $a pool.math = $x pool.math
scoreboard players operation $a pool.math *= #1000 pool.const
function pool:math/div_1e4
scoreboard players operation $a pool.math = $out pool.math
scoreboard players operation $b pool.math = $mu_s_g pool.const
scoreboard players operation $b pool.math *= #-1 pool.const
function pool:math/mul_unit
scoreboard players operation @s pool.ax = $out pool.math
scoreboard players operation $b pool.math = $len pool.math
scoreboard players operation $a pool.math = $z pool.math
scoreboard players operation $a pool.math *= #1000 pool.const
function pool:math/div_1e4
scoreboard players operation $a pool.math = $out pool.math
scoreboard players operation $b pool.math = $mu_s_g pool.const
scoreboard players operation $b pool.math *= #-1 pool.const
function pool:math/mul_unit
scoreboard players operation @s pool.az = $out pool.math
# the fine state, 1/2000 um/tick (|2000 v| < 2^31 for |v| < 1.07e6 um/tick, 21 m/s: the strike
# gives at most 10 m/s, a collision passes speeds on)
scoreboard players set @s pool.px 0
scoreboard players set @s pool.pz 0
scoreboard players operation @s pool.fvx = @s pool.vx
scoreboard players operation @s pool.fvx *= #2000 pool.const
scoreboard players operation @s pool.fvz = @s pool.vz
scoreboard players operation @s pool.fvz *= #2000 pool.const
scoreboard players operation @s pool.fwx = @s pool.wx
scoreboard players operation @s pool.fwx *= #2000 pool.const
scoreboard players operation @s pool.fwz = @s pool.wz
scoreboard players operation @s pool.fwz *= #2000 pool.const
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
