# pool:math/gap — the gap between two balls whose centres are ($x, $z) apart: $out = |(x, z)| - D
# with D = 2R + 1, to 1 um, and the unit vector n = (x, z) / |(x, z)| (x 10000) in $ux $uz;
# $out = 2001 (and $ux $uz unchanged) when the gap is more than 2 mm. Exact where
# pool:math/normalize's length is within 1e-4 (6 um at 2R: near a tangent that would put a
# contact 0.3 mm along the path; its rescaling to 15 bits loses up to 2 um): the residual
# e = x^2 + z^2 - D^2 is summed exactly from 8-bit halves of the magnitudes (pool:math/gap/square),
# and g = e / (|(x, z)| + D) = e / (2D + g) from g = e / 2D (within 1 um for |g| <= 2 mm).
# Reads: $x $z pool.math. Writes: $out $ux $uz pool.math; temporaries #gap.g
# #gap.e #gap.em #gap.es #gap.h #gap.m #gap.l #gap.q pool.math and those of pool:math/div_round.
scoreboard players set $out pool.math 2001
execute unless score $x pool.math matches -60000..60000 run return 0
execute unless score $z pool.math matches -60000..60000 run return 0
# e = H 65536 + M 256 + Lo, each square split as h 256 + l
scoreboard players operation $a pool.math = $x pool.math
function pool:math/gap/square
scoreboard players operation #gap.e pool.math = #gap.h pool.math
scoreboard players operation #gap.em pool.math = #gap.m pool.math
scoreboard players operation #gap.es pool.math = #gap.l pool.math
scoreboard players operation $a pool.math = $z pool.math
function pool:math/gap/square
scoreboard players operation #gap.e pool.math += #gap.h pool.math
scoreboard players operation #gap.em pool.math += #gap.m pool.math
scoreboard players operation #gap.es pool.math += #gap.l pool.math
scoreboard players operation $a pool.math = $2R pool.const
scoreboard players add $a pool.math 1
function pool:math/gap/square
scoreboard players operation #gap.e pool.math -= #gap.h pool.math
scoreboard players operation #gap.em pool.math -= #gap.m pool.math
scoreboard players operation #gap.es pool.math -= #gap.l pool.math
# |H| <= 4000 for |g| <= 2 mm; more would wrap
execute unless score #gap.e pool.math matches -4000..4000 run return run scoreboard players set $out pool.math 2001
scoreboard players operation #gap.e pool.math *= #256 pool.const
scoreboard players operation #gap.e pool.math += #gap.em pool.math
scoreboard players operation #gap.e pool.math *= #256 pool.const
scoreboard players operation #gap.e pool.math += #gap.es pool.math
scoreboard players operation $a pool.math = #gap.e pool.math
scoreboard players operation $b pool.math = $2R pool.const
scoreboard players add $b pool.math 1
scoreboard players operation $b pool.math *= #2 pool.const
function pool:math/div_round
execute unless score $out pool.math matches -2000..2000 run return run scoreboard players set $out pool.math 2001
scoreboard players operation $b pool.math += $out pool.math
function pool:math/div_round
scoreboard players operation #gap.g pool.math = $out pool.math
# n = d / (D + g)
scoreboard players operation $b pool.math = $2R pool.const
scoreboard players add $b pool.math 1
scoreboard players operation $b pool.math += $out pool.math
scoreboard players operation $a pool.math = $x pool.math
scoreboard players operation $a pool.math *= #10000 pool.const
function pool:math/div_round
scoreboard players operation $ux pool.math = $out pool.math
scoreboard players operation $a pool.math = $z pool.math
scoreboard players operation $a pool.math *= #10000 pool.const
function pool:math/div_round
scoreboard players operation $uz pool.math = $out pool.math
scoreboard players operation $out pool.math = #gap.g pool.math
