# pool:physics/resolve/ball_ball/collide — elastic collision of @s (ball a) with ball b (errata
# 3.x): n = (r_b - r_a)/|r_b - r_a|, s = (v_a - v_b) . n; if s > 0: v_a -= s n, v_b += s n.
# The same integer impulse goes to both balls, so momentum is conserved exactly. Spins unchanged.
# Reads: @s pool.x pool.z pool.vx pool.vz; #ball_ball.b.x #ball_ball.b.z #ball_ball.b.vx
# #ball_ball.b.vz pool.tmp.
# Writes: @s pool.vx pool.vz, #ball_ball.b.vx #ball_ball.b.vz pool.tmp, #ball_ball.hit pool.tmp (1
# when they collided, else 0); temporaries #ball_ball.jx #ball_ball.jz pool.tmp and the math
# library's. The caller starts both balls' new phases.
scoreboard players set #ball_ball.hit pool.tmp 0
scoreboard players operation $x pool.math = #ball_ball.b.x pool.tmp
scoreboard players operation $x pool.math -= @s pool.x
scoreboard players operation $z pool.math = #ball_ball.b.z pool.tmp
scoreboard players operation $z pool.math -= @s pool.z
function pool:math/normalize
scoreboard players operation $a pool.math = @s pool.vx
scoreboard players operation $a pool.math -= #ball_ball.b.vx pool.tmp
scoreboard players operation $b pool.math = $ux pool.math
function pool:math/mul_unit
scoreboard players operation #ball_ball.jx pool.tmp = $out pool.math
scoreboard players operation $a pool.math = @s pool.vz
scoreboard players operation $a pool.math -= #ball_ball.b.vz pool.tmp
scoreboard players operation $b pool.math = $uz pool.math
function pool:math/mul_unit
scoreboard players operation #ball_ball.jx pool.tmp += $out pool.math
execute if score #ball_ball.jx pool.tmp matches ..0 run return 0
scoreboard players set #ball_ball.hit pool.tmp 1
# impulse s n
scoreboard players operation $a pool.math = #ball_ball.jx pool.tmp
function pool:math/mul_unit
scoreboard players operation #ball_ball.jz pool.tmp = $out pool.math
scoreboard players operation $b pool.math = $ux pool.math
function pool:math/mul_unit
scoreboard players operation #ball_ball.jx pool.tmp = $out pool.math
scoreboard players operation @s pool.vx -= #ball_ball.jx pool.tmp
scoreboard players operation @s pool.vz -= #ball_ball.jz pool.tmp
scoreboard players operation #ball_ball.b.vx pool.tmp += #ball_ball.jx pool.tmp
scoreboard players operation #ball_ball.b.vz pool.tmp += #ball_ball.jz pool.tmp
