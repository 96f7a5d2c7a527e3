# pool:physics/resolve/ball_ball/touch/relative — the move of a Newton step of
# pool:physics/resolve/ball_ball/touch/step along the relative velocity: (v_a - v_b) g / c, the
# time g / c that closes the gap on straight paths (|v_a - v_b| g < 2^31: each |v| <= 5e5 um/tick,
# |g| <= 2000 um).
# Reads: @s pool.vx pool.vz, #ball_ball.b.vx #ball_ball.b.vz #ball_ball.g #ball_ball.c pool.tmp.
# Writes: #ball_ball.sx #ball_ball.sz pool.tmp and the math library's temporaries.
scoreboard players operation $b pool.math = #ball_ball.c pool.tmp
scoreboard players operation $a pool.math = @s pool.vx
scoreboard players operation $a pool.math -= #ball_ball.b.vx pool.tmp
scoreboard players operation $a pool.math *= #ball_ball.g pool.tmp
function pool:math/div_round
scoreboard players operation #ball_ball.sx pool.tmp = $out pool.math
scoreboard players operation $a pool.math = @s pool.vz
scoreboard players operation $a pool.math -= #ball_ball.b.vz pool.tmp
scoreboard players operation $a pool.math *= #ball_ball.g pool.tmp
function pool:math/div_round
scoreboard players operation #ball_ball.sz pool.tmp = $out pool.math
