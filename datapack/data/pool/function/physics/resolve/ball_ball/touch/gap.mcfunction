# pool:physics/resolve/ball_ball/touch/gap — #ball_ball.g = |r_b - r_a| - D with D = 2R + 1, to 1 um,
# and the unit normal n = (r_b - r_a) / |r_b - r_a| (x 10000) in $ux $uz; g = 2001 when it is more
# than 2 mm. Exact where pool:math/normalize's length is within 1e-4 (6 um at 2R: near a tangent
# that would put the contact 0.3 mm along the path): the residual e = dx^2 + dz^2 - D^2 is summed
# exactly from 8-bit halves of the magnitudes (pool:physics/resolve/ball_ball/touch/square), and
# g = e / (|r_b - r_a| + D) = e / (2D + g) from g = e / 2D (within 1 um for |g| <= 2 mm).
# Reads: @s pool.x pool.z, #ball_ball.b.x #ball_ball.b.z pool.tmp. Writes: #ball_ball.g #ball_ball.e
# #ball_ball.em #ball_ball.es #ball_ball.h #ball_ball.m #ball_ball.l #ball_ball.q pool.tmp, $x $z
# $ux $uz and the math library's temporaries.
scoreboard players set #ball_ball.g pool.tmp 2001
scoreboard players operation $x pool.math = #ball_ball.b.x pool.tmp
scoreboard players operation $x pool.math -= @s pool.x
execute unless score $x pool.math matches -60000..60000 run return 0
scoreboard players operation $z pool.math = #ball_ball.b.z pool.tmp
scoreboard players operation $z pool.math -= @s pool.z
execute unless score $z pool.math matches -60000..60000 run return 0
# e = H 65536 + M 256 + Lo, each square split as h 256 + l
scoreboard players operation $a pool.math = $x pool.math
function pool:physics/resolve/ball_ball/touch/square
scoreboard players operation #ball_ball.e pool.tmp = #ball_ball.h pool.tmp
scoreboard players operation #ball_ball.em pool.tmp = #ball_ball.m pool.tmp
scoreboard players operation #ball_ball.es pool.tmp = #ball_ball.l pool.tmp
scoreboard players operation $a pool.math = $z pool.math
function pool:physics/resolve/ball_ball/touch/square
scoreboard players operation #ball_ball.e pool.tmp += #ball_ball.h pool.tmp
scoreboard players operation #ball_ball.em pool.tmp += #ball_ball.m pool.tmp
scoreboard players operation #ball_ball.es pool.tmp += #ball_ball.l pool.tmp
scoreboard players operation $a pool.math = $2R pool.const
scoreboard players add $a pool.math 1
function pool:physics/resolve/ball_ball/touch/square
scoreboard players operation #ball_ball.e pool.tmp -= #ball_ball.h pool.tmp
scoreboard players operation #ball_ball.em pool.tmp -= #ball_ball.m pool.tmp
scoreboard players operation #ball_ball.es pool.tmp -= #ball_ball.l pool.tmp
# |H| <= 4000 for |g| <= 2 mm; more would wrap
execute unless score #ball_ball.e pool.tmp matches -4000..4000 run return 0
scoreboard players operation #ball_ball.e pool.tmp *= #256 pool.const
scoreboard players operation #ball_ball.e pool.tmp += #ball_ball.em pool.tmp
scoreboard players operation #ball_ball.e pool.tmp *= #256 pool.const
scoreboard players operation #ball_ball.e pool.tmp += #ball_ball.es pool.tmp
scoreboard players operation $a pool.math = #ball_ball.e pool.tmp
scoreboard players operation $b pool.math = $2R pool.const
scoreboard players add $b pool.math 1
scoreboard players operation $b pool.math *= #2 pool.const
function pool:math/div_round
execute unless score $out pool.math matches -2000..2000 run return 0
scoreboard players operation $b pool.math += $out pool.math
function pool:math/div_round
scoreboard players operation #ball_ball.g pool.tmp = $out pool.math
# n = d / (D + g)
scoreboard players operation $b pool.math = $2R pool.const
scoreboard players add $b pool.math 1
scoreboard players operation $b pool.math += #ball_ball.g pool.tmp
scoreboard players operation $a pool.math = $x pool.math
scoreboard players operation $a pool.math *= #10000 pool.const
function pool:math/div_round
scoreboard players operation $ux pool.math = $out pool.math
scoreboard players operation $a pool.math = $z pool.math
scoreboard players operation $a pool.math *= #10000 pool.const
function pool:math/div_round
scoreboard players operation $uz pool.math = $out pool.math
