# pool:physics/resolve/ball_ball/touch/normal — the move of a Newton step of
# pool:physics/resolve/ball_ball/touch/step along the normal: g n (n from a to b, from
# pool:physics/resolve/ball_ball/touch/gap), which puts the pair at 2R + 1 apart.
# Reads: #ball_ball.g pool.tmp, $ux $uz pool.math. Writes: #ball_ball.sx #ball_ball.sz pool.tmp and
# the math library's temporaries.
scoreboard players operation $a pool.math = #ball_ball.g pool.tmp
scoreboard players operation $b pool.math = $ux pool.math
function pool:math/mul_unit
scoreboard players operation #ball_ball.sx pool.tmp = $out pool.math
scoreboard players operation $b pool.math = $uz pool.math
function pool:math/mul_unit
scoreboard players operation #ball_ball.sz pool.tmp = $out pool.math
