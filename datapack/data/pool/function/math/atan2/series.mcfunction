# pool:math/atan2/series — $out = atan(w) in centidegrees for 0 <= w <= 10000 (w x 10000).
# Reads: #atan2.w pool.math. Writes: $out pool.math; temporaries #atan2.y #atan2.p pool.math.
# atan w = w (0.99987 - 0.33030 y + 0.18014 y^2 - 0.08513 y^3 + 0.02084 y^4), y = w^2;
# coefficients x 100000, y x 10000.
scoreboard players operation #atan2.y pool.math = #atan2.w pool.math
scoreboard players operation #atan2.y pool.math *= #atan2.w pool.math
scoreboard players add #atan2.y pool.math 5000
scoreboard players operation #atan2.y pool.math /= #10000 pool.const
scoreboard players set $out pool.math 2084
function pool:math/atan2/horner
scoreboard players remove $out pool.math 8513
function pool:math/atan2/horner
scoreboard players add $out pool.math 18014
function pool:math/atan2/horner
scoreboard players remove $out pool.math 33030
function pool:math/atan2/horner
scoreboard players add $out pool.math 99987
# radians x 100000 = w p / 10000; centidegrees = that x 18000/pi / 100000 = x 14324/250000
scoreboard players operation $out pool.math *= #atan2.w pool.math
scoreboard players add $out pool.math 5000
scoreboard players operation $out pool.math /= #10000 pool.const
scoreboard players set #atan2.p pool.math 14324
scoreboard players operation $out pool.math *= #atan2.p pool.math
scoreboard players add $out pool.math 125000
scoreboard players set #atan2.p pool.math 250000
scoreboard players operation $out pool.math /= #atan2.p pool.math
