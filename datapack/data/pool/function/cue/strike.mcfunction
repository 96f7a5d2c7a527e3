# pool:cue/strike — the cue hits @s (errata 5.x with mu = tan(theta): the impulse lies
# along the cue, the tip does not slip). With cue direction d (azimuth alpha, butt raised by
# elevation e), tip offset a (right), b (up) in ball radii and sin^2(theta) = a^2 + b^2:
#   ball speed V = 2 v_cue / (1 + m_b/m_s + (5/2) sin^2(theta)), horizontal part V cos(e) d_xz,
#   w = (5/2) V (b cos(alpha) - a sin(e) sin(alpha), b sin(alpha) + a sin(e) cos(alpha)),
#   wy = (5/2) V a cos(e)   (the vertical part of V goes into the table).
# Reads: $shot.angle $shot.elevation (centidegrees), $shot.speed (cue speed, mm/s, <= 6500),
# $shot.tip_x $shot.tip_y (per mille of R, a^2 + b^2 <= 0.25) on pool.game.
# Writes: @s pool.vx pool.vz pool.wx pool.wz pool.wy and the phase scores;
# temporaries #cue.ca #cue.sa #cue.ce #cue.se #cue.v #cue.p pool.tmp and the math library's.
# cos(e) is x 100000 (pool:math/cos_1e5: 1745 at 89 degrees, where x 10000 would be 0.3 % off); the
# spin factors P are kept in 1e-8 (per mille x 100000) up to the product with V
# (pool:cue/spin_component), so that a tip of 1 per mille still gets its spin to 0.1 %.
scoreboard players operation $a pool.math = $shot.angle pool.game
function pool:math/sincos
scoreboard players operation #cue.ca pool.tmp = $cos pool.math
scoreboard players operation #cue.sa pool.tmp = $sin pool.math
scoreboard players operation $a pool.math = $shot.elevation pool.game
function pool:math/sincos
scoreboard players operation #cue.se pool.tmp = $sin pool.math
scoreboard players operation $a pool.math = $shot.elevation pool.game
function pool:math/cos_1e5
scoreboard players operation #cue.ce pool.tmp = $out pool.math
# D = 10^6 (1 + m_b/m_s) + (5/2)(a^2 + b^2) with m_b/m_s = 0.170/0.567 = 0.299824
scoreboard players operation $b pool.math = $shot.tip_x pool.game
scoreboard players operation $b pool.math *= $shot.tip_x pool.game
scoreboard players operation #cue.p pool.tmp = $shot.tip_y pool.game
scoreboard players operation #cue.p pool.tmp *= $shot.tip_y pool.game
scoreboard players operation $b pool.math += #cue.p pool.tmp
scoreboard players operation $b pool.math *= #5 pool.const
scoreboard players operation $b pool.math /= #2 pool.const
scoreboard players add $b pool.math 1299824
# V (um/tick) = 2 v_cue (mm/s) * 1000 / 20 * 10^6 / D = 10000 (10000 v_cue) / D
scoreboard players operation $a pool.math = $shot.speed pool.game
scoreboard players operation $a pool.math *= #10000 pool.const
function pool:math/div_1e4
scoreboard players operation #cue.v pool.tmp = $out pool.math
# velocity
scoreboard players operation $a pool.math = #cue.v pool.tmp
scoreboard players operation $b pool.math = #cue.ce pool.tmp
function pool:math/mul_1e5
scoreboard players operation $a pool.math = $out pool.math
scoreboard players operation $b pool.math = #cue.ca pool.tmp
function pool:math/mul_unit
scoreboard players operation @s pool.vx = $out pool.math
scoreboard players operation $b pool.math = #cue.sa pool.tmp
function pool:math/mul_unit
scoreboard players operation @s pool.vz = $out pool.math
# spin: each factor P in 1e-8 (per mille x 100000)
scoreboard players operation $a pool.math = #cue.se pool.tmp
scoreboard players operation $b pool.math = #cue.sa pool.tmp
function pool:math/mul_unit
scoreboard players operation #cue.p pool.tmp = $out pool.math
scoreboard players operation #cue.p pool.tmp *= $shot.tip_x pool.game
scoreboard players operation #cue.p pool.tmp *= #-1 pool.const
scoreboard players operation $a pool.math = $shot.tip_y pool.game
scoreboard players operation $a pool.math *= #cue.ca pool.tmp
scoreboard players operation #cue.p pool.tmp += $a pool.math
scoreboard players operation #cue.p pool.tmp *= #10 pool.const
function pool:cue/spin_component
scoreboard players operation @s pool.wx = $out pool.math
scoreboard players operation $a pool.math = #cue.se pool.tmp
scoreboard players operation $b pool.math = #cue.ca pool.tmp
function pool:math/mul_unit
scoreboard players operation #cue.p pool.tmp = $out pool.math
scoreboard players operation #cue.p pool.tmp *= $shot.tip_x pool.game
scoreboard players operation $a pool.math = $shot.tip_y pool.game
scoreboard players operation $a pool.math *= #cue.sa pool.tmp
scoreboard players operation #cue.p pool.tmp += $a pool.math
scoreboard players operation #cue.p pool.tmp *= #10 pool.const
function pool:cue/spin_component
scoreboard players operation @s pool.wz = $out pool.math
scoreboard players operation #cue.p pool.tmp = $shot.tip_x pool.game
scoreboard players operation #cue.p pool.tmp *= #cue.ce pool.tmp
function pool:cue/spin_component
scoreboard players operation @s pool.wy = $out pool.math
function pool:physics/motion/start
