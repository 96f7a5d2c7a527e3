# pool:physics/resolve/ball_ball/touch/closing — the closing speed #ball_ball.c = (v_a - v_b) . n of
# @s (a) and b along the unit normal n ($ux $uz, from pool:physics/resolve/ball_ball/touch/gap).
# Reads: @s pool.vx pool.vz, #ball_ball.b.vx #ball_ball.b.vz pool.tmp, $ux $uz pool.math. Writes:
# #ball_ball.c pool.tmp; the math library's temporaries.
scoreboard players operation $a pool.math = @s pool.vx
scoreboard players operation $a pool.math -= #ball_ball.b.vx pool.tmp
scoreboard players operation $b pool.math = $ux pool.math
function pool:math/mul_unit
scoreboard players operation #ball_ball.c pool.tmp = $out pool.math
scoreboard players operation $a pool.math = @s pool.vz
scoreboard players operation $a pool.math -= #ball_ball.b.vz pool.tmp
scoreboard players operation $b pool.math = $uz pool.math
function pool:math/mul_unit
scoreboard players operation #ball_ball.c pool.tmp += $out pool.math
