# pool:physics/resolve/ball_ball/touch/gap — #ball_ball.g = |r_b - r_a| - D with D = 2R + 1, to 1 um,
# and the unit normal n = (r_b - r_a) / |r_b - r_a| (x 10000) in $ux $uz, by pool:math/gap (exact;
# g = 2001 when it is more than 2 mm).
# Reads: @s pool.x pool.z, #ball_ball.b.x #ball_ball.b.z pool.tmp. Writes: #ball_ball.g pool.tmp,
# $x $z $ux $uz and the math library's temporaries.
scoreboard players operation $x pool.math = #ball_ball.b.x pool.tmp
scoreboard players operation $x pool.math -= @s pool.x
scoreboard players operation $z pool.math = #ball_ball.b.z pool.tmp
scoreboard players operation $z pool.math -= @s pool.z
function pool:math/gap
scoreboard players operation #ball_ball.g pool.tmp = $out pool.math
