# pool:math/sincos/cos_series — #sincos.c = 1 - t/2 (1 - t/12 (1 - t/30 (1 - t/56))), x 10000.
# Reads: #sincos.t pool.math (t = x^2/10000 <= 6169). Writes: #sincos.c pool.math; temporary
# #sincos.p.
scoreboard players operation #sincos.c pool.math = #sincos.t pool.math
scoreboard players set #sincos.p pool.math 56
scoreboard players operation #sincos.c pool.math /= #sincos.p pool.math
scoreboard players operation #sincos.c pool.math *= #-1 pool.const
scoreboard players add #sincos.c pool.math 10000
scoreboard players operation #sincos.c pool.math *= #sincos.t pool.math
scoreboard players add #sincos.c pool.math 150000
scoreboard players set #sincos.p pool.math 300000
scoreboard players operation #sincos.c pool.math /= #sincos.p pool.math
scoreboard players operation #sincos.c pool.math *= #-1 pool.const
scoreboard players add #sincos.c pool.math 10000
scoreboard players operation #sincos.c pool.math *= #sincos.t pool.math
scoreboard players add #sincos.c pool.math 60000
scoreboard players set #sincos.p pool.math 120000
scoreboard players operation #sincos.c pool.math /= #sincos.p pool.math
scoreboard players operation #sincos.c pool.math *= #-1 pool.const
scoreboard players add #sincos.c pool.math 10000
scoreboard players operation #sincos.c pool.math *= #sincos.t pool.math
scoreboard players add #sincos.c pool.math 10000
scoreboard players set #sincos.p pool.math 20000
scoreboard players operation #sincos.c pool.math /= #sincos.p pool.math
scoreboard players operation #sincos.c pool.math *= #-1 pool.const
scoreboard players add #sincos.c pool.math 10000
