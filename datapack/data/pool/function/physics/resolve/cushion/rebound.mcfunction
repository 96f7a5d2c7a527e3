# pool:physics/resolve/cushion/rebound — @s hits a cushion (errata 4.x, Coulomb form with stick
# limit): v_n' = -e v_n; slip along the rail s = v_t - wy; dv_t = -sign(s) min(mu_c (1+e)|v_n|,
# (2/7)|s|); wy' = wy - (5/2) dv_t; then a new motion phase (the horizontal spin w is unchanged).
# Reads: #cushion.nx #cushion.nz pool.tmp (the cushion's inward normal, one of them +-1, the other
# 0); @s pool.vx pool.vz pool.wy. Writes: @s pool.vx pool.vz pool.wy and the phase scores;
# temporaries #cushion.vn #cushion.vt #cushion.sl #cushion.lim #cushion.d pool.tmp and the math
# library's.
# v_n = v . n, v_t = v . t with t = y x n = (nz, -nx)
scoreboard players operation #cushion.vn pool.tmp = @s pool.vx
scoreboard players operation #cushion.vn pool.tmp *= #cushion.nx pool.tmp
scoreboard players operation #cushion.d pool.tmp = @s pool.vz
scoreboard players operation #cushion.d pool.tmp *= #cushion.nz pool.tmp
scoreboard players operation #cushion.vn pool.tmp += #cushion.d pool.tmp
scoreboard players operation #cushion.vt pool.tmp = @s pool.vx
scoreboard players operation #cushion.vt pool.tmp *= #cushion.nz pool.tmp
scoreboard players operation #cushion.d pool.tmp = @s pool.vz
scoreboard players operation #cushion.d pool.tmp *= #cushion.nx pool.tmp
scoreboard players operation #cushion.vt pool.tmp -= #cushion.d pool.tmp
# Coulomb limit mu_c (1 + e) |v_n| (constants x 10000)
scoreboard players operation $a pool.math = #cushion.vn pool.tmp
execute if score $a pool.math matches ..-1 run scoreboard players operation $a pool.math *= #-1 pool.const
scoreboard players operation $b pool.math = $e_cushion pool.const
scoreboard players add $b pool.math 10000
scoreboard players operation $b pool.math *= $mu_cushion pool.const
scoreboard players operation $b pool.math /= #10000 pool.const
function pool:math/mul_unit
scoreboard players operation #cushion.lim pool.tmp = $out pool.math
# stick limit (2/7)|s|
scoreboard players operation #cushion.sl pool.tmp = #cushion.vt pool.tmp
scoreboard players operation #cushion.sl pool.tmp -= @s pool.wy
scoreboard players operation $a pool.math = #cushion.sl pool.tmp
execute if score $a pool.math matches ..-1 run scoreboard players operation $a pool.math *= #-1 pool.const
scoreboard players operation $a pool.math *= #2 pool.const
scoreboard players operation $b pool.math = #7 pool.const
function pool:math/div_round
scoreboard players operation #cushion.lim pool.tmp < $out pool.math
# dv_t = -sign(s) lim
execute if score #cushion.sl pool.tmp matches 1.. run scoreboard players operation #cushion.vt pool.tmp -= #cushion.lim pool.tmp
execute if score #cushion.sl pool.tmp matches ..-1 run scoreboard players operation #cushion.vt pool.tmp += #cushion.lim pool.tmp
execute if score #cushion.sl pool.tmp matches ..-1 run scoreboard players operation #cushion.lim pool.tmp *= #-1 pool.const
# wy -= (5/2) dv_t = +(5/2) sign(s) lim
scoreboard players operation $a pool.math = #cushion.lim pool.tmp
scoreboard players operation $a pool.math *= #5 pool.const
scoreboard players operation $b pool.math = #2 pool.const
function pool:math/div_round
scoreboard players operation @s pool.wy += $out pool.math
# v_n' = -e v_n
scoreboard players operation $a pool.math = #cushion.vn pool.tmp
scoreboard players operation $b pool.math = $e_cushion pool.const
function pool:math/mul_unit
scoreboard players operation #cushion.vn pool.tmp = $out pool.math
scoreboard players operation #cushion.vn pool.tmp *= #-1 pool.const
# back to x, z: v = v_n n + v_t t
scoreboard players operation @s pool.vx = #cushion.vn pool.tmp
scoreboard players operation @s pool.vx *= #cushion.nx pool.tmp
scoreboard players operation #cushion.d pool.tmp = #cushion.vt pool.tmp
scoreboard players operation #cushion.d pool.tmp *= #cushion.nz pool.tmp
scoreboard players operation @s pool.vx += #cushion.d pool.tmp
scoreboard players operation @s pool.vz = #cushion.vn pool.tmp
scoreboard players operation @s pool.vz *= #cushion.nz pool.tmp
scoreboard players operation #cushion.d pool.tmp = #cushion.vt pool.tmp
scoreboard players operation #cushion.d pool.tmp *= #cushion.nx pool.tmp
scoreboard players operation @s pool.vz -= #cushion.d pool.tmp
function pool:physics/motion/start
