# pool:math/sincos/cos_series — #c = 1 - t/2 (1 - t/12 (1 - t/30 (1 - t/56))), x 10000.
# Reads: #t pool.math (t = x^2/10000 <= 6169). Writes: #c pool.math; temporary #p.
scoreboard players operation #c pool.math = #t pool.math
scoreboard players set #p pool.math 56
scoreboard players operation #c pool.math /= #p pool.math
scoreboard players operation #c pool.math *= #-1 pool.const
scoreboard players add #c pool.math 10000
scoreboard players operation #c pool.math *= #t pool.math
scoreboard players add #c pool.math 150000
scoreboard players set #p pool.math 300000
scoreboard players operation #c pool.math /= #p pool.math
scoreboard players operation #c pool.math *= #-1 pool.const
scoreboard players add #c pool.math 10000
scoreboard players operation #c pool.math *= #t pool.math
scoreboard players add #c pool.math 60000
scoreboard players set #p pool.math 120000
scoreboard players operation #c pool.math /= #p pool.math
scoreboard players operation #c pool.math *= #-1 pool.const
scoreboard players add #c pool.math 10000
scoreboard players operation #c pool.math *= #t pool.math
scoreboard players add #c pool.math 10000
scoreboard players set #p pool.math 20000
scoreboard players operation #c pool.math /= #p pool.math
scoreboard players operation #c pool.math *= #-1 pool.const
scoreboard players add #c pool.math 10000
