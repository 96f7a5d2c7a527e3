# pool:physics/resolve/ball_ball/touch — bring @s (a) and b (#ball_ball.b.*) to touching, |r_b -
# r_a| = 2R + 10 um (between 2R and the sweep's $contact), by moving both along their velocities by
# the same small time g / c (g = gap, c = closing speed): the sweep's chords miss the curved sliding
# path by up to 0.6 mm, which would tilt the contact normal.
# Reads/writes: @s pool.x pool.z, #ball_ball.b.x #ball_ball.b.z pool.tmp; reads @s pool.vx pool.vz,
# #ball_ball.b.vx #ball_ball.b.vz.
# Temporaries #ball_ball.g #ball_ball.c pool.tmp and the math library's.
scoreboard players operation $x pool.math = #ball_ball.b.x pool.tmp
scoreboard players operation $x pool.math -= @s pool.x
scoreboard players operation $z pool.math = #ball_ball.b.z pool.tmp
scoreboard players operation $z pool.math -= @s pool.z
function pool:math/normalize
scoreboard players operation #ball_ball.g pool.tmp = $len pool.math
scoreboard players operation #ball_ball.g pool.tmp -= $2R pool.const
scoreboard players remove #ball_ball.g pool.tmp 10
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
execute if score #ball_ball.c pool.tmp matches ..0 run return 0
execute unless score #ball_ball.g pool.tmp matches -2000..2000 run return 0
# a nearly tangent closing speed would carry both balls far along their paths (time g / c) into
# other balls: shift only when each moves at most 8 |g|
execute if function pool:physics/resolve/ball_ball/too_tangent run return 0
scoreboard players operation $b pool.math = #ball_ball.c pool.tmp
scoreboard players operation $a pool.math = @s pool.vx
scoreboard players operation $a pool.math *= #ball_ball.g pool.tmp
function pool:math/div_round
scoreboard players operation @s pool.x += $out pool.math
scoreboard players operation $a pool.math = @s pool.vz
scoreboard players operation $a pool.math *= #ball_ball.g pool.tmp
function pool:math/div_round
scoreboard players operation @s pool.z += $out pool.math
scoreboard players operation $a pool.math = #ball_ball.b.vx pool.tmp
scoreboard players operation $a pool.math *= #ball_ball.g pool.tmp
function pool:math/div_round
scoreboard players operation #ball_ball.b.x pool.tmp += $out pool.math
scoreboard players operation $a pool.math = #ball_ball.b.vz pool.tmp
scoreboard players operation $a pool.math *= #ball_ball.g pool.tmp
function pool:math/div_round
scoreboard players operation #ball_ball.b.z pool.tmp += $out pool.math
