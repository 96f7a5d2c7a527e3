# pool:math/sincos/octant_upper — #s = sin r, #c = cos r for 4500 < r < 9000 via the complement.
# Reads: #r pool.math. Writes: #s #c pool.math; temporaries of pool:math/sincos/octant.
scoreboard players operation #r pool.math *= #-1 pool.const
scoreboard players add #r pool.math 9000
function pool:math/sincos/octant
scoreboard players operation #r pool.math = #s pool.math
scoreboard players operation #s pool.math = #c pool.math
scoreboard players operation #c pool.math = #r pool.math
