# pool:math/cos_1e5/horner — one Horner step of pool:math/cos_1e5's series: $out = 100000 - t $out /
# (k 100000), rounded.
# Reads: $out #cos_1e5.t #cos_1e5.k pool.math (0 <= $out <= 100000, t <= 61685). Writes: $out
# pool.math; the temporaries of pool:math/mul_1e5, pool:math/div_round.
scoreboard players operation $a pool.math = #cos_1e5.t pool.math
scoreboard players operation $b pool.math = $out pool.math
function pool:math/mul_1e5
scoreboard players operation $a pool.math = $out pool.math
scoreboard players operation $b pool.math = #cos_1e5.k pool.math
function pool:math/div_round
scoreboard players operation $out pool.math *= #-1 pool.const
scoreboard players add $out pool.math 100000
