# pool:math/sincos/octant — #sincos.s = sin r, #sincos.c = cos r for 0 <= r <= 4500 centidegrees (x
# 10000).
# Reads: #sincos.r pool.math. Writes: #sincos.s #sincos.c pool.math; temporaries #sincos.x #sincos.t
# #sincos.p pool.math.
# x = r * pi/18000 in 1/10000 rad (pi/1.8 = 1.745329); t = x^2 in 1/10000 rad^2
scoreboard players operation #sincos.x pool.math = #sincos.r pool.math
scoreboard players set #sincos.p pool.math 174533
scoreboard players operation #sincos.x pool.math *= #sincos.p pool.math
scoreboard players add #sincos.x pool.math 50000
scoreboard players set #sincos.p pool.math 100000
scoreboard players operation #sincos.x pool.math /= #sincos.p pool.math
scoreboard players operation #sincos.t pool.math = #sincos.x pool.math
scoreboard players operation #sincos.t pool.math *= #sincos.x pool.math
scoreboard players add #sincos.t pool.math 5000
scoreboard players operation #sincos.t pool.math /= #10000 pool.const
# sin x = x (1 - t/6 (1 - t/20 (1 - t/42)))
function pool:math/sincos/sin_series
# cos x = 1 - t/2 (1 - t/12 (1 - t/30 (1 - t/56)))
function pool:math/sincos/cos_series
