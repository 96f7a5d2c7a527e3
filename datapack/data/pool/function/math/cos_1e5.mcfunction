# pool:math/cos_1e5 — $out = cos($a) x 100000 for 0 <= $a <= 9000 centidegrees, within 1 unit: the
# cue's elevation, whose cosine pool:math/sincos (x 10000) gives only to 0.3 % at 89 degrees.
# Reads: $a pool.math. Writes: $out pool.math; temporaries #cos_1e5.s #cos_1e5.x #cos_1e5.t
# #cos_1e5.k pool.math and those of pool:math/div_round, pool:math/mul_1e5.
# Up to 45 degrees cos x by its series; above, sin y of the complement y = 90 degrees - a, small near
# the vertical, so that its few units keep their relative precision. x in 1e-5 rad, t = x^2 in 1e-5.
scoreboard players set #cos_1e5.s pool.math 0
execute if score $a pool.math matches 4501.. run scoreboard players set #cos_1e5.s pool.math 1
execute if score #cos_1e5.s pool.math matches 1 run scoreboard players operation $a pool.math *= #-1 pool.const
execute if score #cos_1e5.s pool.math matches 1 run scoreboard players add $a pool.math 9000
# x = angle x pi/18000 x 100000 = angle x 17.4533
scoreboard players set #cos_1e5.k pool.math 174533
scoreboard players operation $a pool.math *= #cos_1e5.k pool.math
scoreboard players operation $b pool.math = #10000 pool.const
function pool:math/div_round
scoreboard players operation #cos_1e5.x pool.math = $out pool.math
scoreboard players operation $a pool.math = $out pool.math
scoreboard players operation $b pool.math = $out pool.math
function pool:math/mul_1e5
scoreboard players operation #cos_1e5.t pool.math = $out pool.math
scoreboard players set $out pool.math 100000
execute if score #cos_1e5.s pool.math matches 1 run return run function pool:math/cos_1e5/sin
# cos x = 1 - t/2 (1 - t/12 (1 - t/30 (1 - t/56 (1 - t/90))))
scoreboard players set #cos_1e5.k pool.math 90
function pool:math/cos_1e5/horner
scoreboard players set #cos_1e5.k pool.math 56
function pool:math/cos_1e5/horner
scoreboard players set #cos_1e5.k pool.math 30
function pool:math/cos_1e5/horner
scoreboard players set #cos_1e5.k pool.math 12
function pool:math/cos_1e5/horner
scoreboard players set #cos_1e5.k pool.math 2
function pool:math/cos_1e5/horner
