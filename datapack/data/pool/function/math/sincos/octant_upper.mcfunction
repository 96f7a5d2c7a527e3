# pool:math/sincos/octant_upper — #sincos.s = sin r, #sincos.c = cos r for 4500 < r < 9000 via the
# complement.
# Reads: #sincos.r pool.math. Writes: #sincos.s #sincos.c pool.math; temporaries of
# pool:math/sincos/octant.
scoreboard players operation #sincos.r pool.math *= #-1 pool.const
scoreboard players add #sincos.r pool.math 9000
function pool:math/sincos/octant
scoreboard players operation #sincos.r pool.math = #sincos.s pool.math
scoreboard players operation #sincos.s pool.math = #sincos.c pool.math
scoreboard players operation #sincos.c pool.math = #sincos.r pool.math
