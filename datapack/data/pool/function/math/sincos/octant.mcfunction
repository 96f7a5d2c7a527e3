# pool:math/sincos/octant — #s = sin r, #c = cos r for 0 <= r <= 4500 centidegrees (x 10000).
# Reads: #r pool.math. Writes: #s #c pool.math; temporaries #x #t #p pool.math.
# x = r * pi/18000 in 1/10000 rad (pi/1.8 = 1.745329); t = x^2 in 1/10000 rad^2
scoreboard players operation #x pool.math = #r pool.math
scoreboard players set #p pool.math 174533
scoreboard players operation #x pool.math *= #p pool.math
scoreboard players add #x pool.math 50000
scoreboard players set #p pool.math 100000
scoreboard players operation #x pool.math /= #p pool.math
scoreboard players operation #t pool.math = #x pool.math
scoreboard players operation #t pool.math *= #x pool.math
scoreboard players add #t pool.math 5000
scoreboard players operation #t pool.math /= #10000 pool.const
# sin x = x (1 - t/6 (1 - t/20 (1 - t/42)))
function pool:math/sincos/sin_series
# cos x = 1 - t/2 (1 - t/12 (1 - t/30 (1 - t/56)))
function pool:math/sincos/cos_series
