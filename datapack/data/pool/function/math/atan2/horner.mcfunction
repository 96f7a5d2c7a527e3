# pool:math/atan2/horner — one Horner step $out = $out * y / 10000, rounded (floor of +half).
# Reads: $out #atan2.y pool.math (|$out| <= 100000, 0 <= y <= 10000). Writes: $out pool.math.
scoreboard players operation $out pool.math *= #atan2.y pool.math
scoreboard players add $out pool.math 5000
scoreboard players operation $out pool.math /= #10000 pool.const
