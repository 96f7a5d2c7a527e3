# pool:physics/resolve/cushion/rebound — @s hits a cushion (errata 4.x, Coulomb form with stick limit):
# v_n' = -e v_n; slip along the rail s = v_t - wy; dv_t = -sign(s) min(mu_c (1+e)|v_n|, (2/7)|s|);
# wy' = wy - (5/2) dv_t; then a new motion phase (the horizontal spin w is unchanged).
# Reads: #nx #nz pool.tmp (the cushion's inward normal, one of them +-1, the other 0);
# @s pool.vx pool.vz pool.wy. Writes: @s pool.vx pool.vz pool.wy and the phase scores;
# temporaries #vn #vt #sl #lim #d pool.tmp and the math library's.
# v_n = v . n, v_t = v . t with t = y x n = (nz, -nx)
scoreboard players operation #vn pool.tmp = @s pool.vx
scoreboard players operation #vn pool.tmp *= #nx pool.tmp
scoreboard players operation #d pool.tmp = @s pool.vz
scoreboard players operation #d pool.tmp *= #nz pool.tmp
scoreboard players operation #vn pool.tmp += #d pool.tmp
scoreboard players operation #vt pool.tmp = @s pool.vx
scoreboard players operation #vt pool.tmp *= #nz pool.tmp
scoreboard players operation #d pool.tmp = @s pool.vz
scoreboard players operation #d pool.tmp *= #nx pool.tmp
scoreboard players operation #vt pool.tmp -= #d pool.tmp
# Coulomb limit mu_c (1 + e) |v_n| (constants x 10000)
scoreboard players operation $a pool.math = #vn pool.tmp
execute if score $a pool.math matches ..-1 run scoreboard players operation $a pool.math *= #-1 pool.const
scoreboard players operation $b pool.math = $e_cushion pool.const
scoreboard players add $b pool.math 10000
scoreboard players operation $b pool.math *= $mu_cushion pool.const
scoreboard players operation $b pool.math /= #10000 pool.const
function pool:math/mul_unit
scoreboard players operation #lim pool.tmp = $out pool.math
# stick limit (2/7)|s|
scoreboard players operation #sl pool.tmp = #vt pool.tmp
scoreboard players operation #sl pool.tmp -= @s pool.wy
scoreboard players operation $a pool.math = #sl pool.tmp
execute if score $a pool.math matches ..-1 run scoreboard players operation $a pool.math *= #-1 pool.const
scoreboard players operation $a pool.math *= #2 pool.const
scoreboard players operation $b pool.math = #7 pool.const
function pool:math/div_round
scoreboard players operation #lim pool.tmp < $out pool.math
# dv_t = -sign(s) lim
execute if score #sl pool.tmp matches 1.. run scoreboard players operation #vt pool.tmp -= #lim pool.tmp
execute if score #sl pool.tmp matches ..-1 run scoreboard players operation #vt pool.tmp += #lim pool.tmp
execute if score #sl pool.tmp matches ..-1 run scoreboard players operation #lim pool.tmp *= #-1 pool.const
# wy -= (5/2) dv_t = +(5/2) sign(s) lim
scoreboard players operation $a pool.math = #lim pool.tmp
scoreboard players operation $a pool.math *= #5 pool.const
scoreboard players operation $b pool.math = #2 pool.const
function pool:math/div_round
scoreboard players operation @s pool.wy += $out pool.math
# v_n' = -e v_n
scoreboard players operation $a pool.math = #vn pool.tmp
scoreboard players operation $b pool.math = $e_cushion pool.const
function pool:math/mul_unit
scoreboard players operation #vn pool.tmp = $out pool.math
scoreboard players operation #vn pool.tmp *= #-1 pool.const
# back to x, z: v = v_n n + v_t t
scoreboard players operation @s pool.vx = #vn pool.tmp
scoreboard players operation @s pool.vx *= #nx pool.tmp
scoreboard players operation #d pool.tmp = #vt pool.tmp
scoreboard players operation #d pool.tmp *= #nz pool.tmp
scoreboard players operation @s pool.vx += #d pool.tmp
scoreboard players operation @s pool.vz = #vn pool.tmp
scoreboard players operation @s pool.vz *= #nz pool.tmp
scoreboard players operation #d pool.tmp = #vt pool.tmp
scoreboard players operation #d pool.tmp *= #nx pool.tmp
scoreboard players operation @s pool.vz -= #d pool.tmp
function pool:physics/motion/start
