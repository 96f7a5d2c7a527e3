# pool:math/sincos/sin_series — #s = x (1 - t/6 (1 - t/20 (1 - t/42))), x 10000.
# Reads: #x #t pool.math (x <= 7854, t = x^2/10000). Writes: #s pool.math; temporary #p.
scoreboard players operation #s pool.math = #t pool.math
scoreboard players set #p pool.math 42
scoreboard players operation #s pool.math /= #p pool.math
scoreboard players operation #s pool.math *= #-1 pool.const
scoreboard players add #s pool.math 10000
scoreboard players operation #s pool.math *= #t pool.math
scoreboard players add #s pool.math 100000
scoreboard players set #p pool.math 200000
scoreboard players operation #s pool.math /= #p pool.math
scoreboard players operation #s pool.math *= #-1 pool.const
scoreboard players add #s pool.math 10000
scoreboard players operation #s pool.math *= #t pool.math
scoreboard players add #s pool.math 30000
scoreboard players set #p pool.math 60000
scoreboard players operation #s pool.math /= #p pool.math
scoreboard players operation #s pool.math *= #-1 pool.const
scoreboard players add #s pool.math 10000
scoreboard players operation #s pool.math *= #x pool.math
scoreboard players add #s pool.math 5000
scoreboard players operation #s pool.math /= #10000 pool.const
