# pool:math/sincos/sin_series — #sincos.s = x (1 - t/6 (1 - t/20 (1 - t/42))), x 10000.
# Reads: #sincos.x #sincos.t pool.math (x <= 7854, t = x^2/10000). Writes: #sincos.s pool.math;
# temporary #sincos.p.
scoreboard players operation #sincos.s pool.math = #sincos.t pool.math
scoreboard players set #sincos.p pool.math 42
scoreboard players operation #sincos.s pool.math /= #sincos.p pool.math
scoreboard players operation #sincos.s pool.math *= #-1 pool.const
scoreboard players add #sincos.s pool.math 10000
scoreboard players operation #sincos.s pool.math *= #sincos.t pool.math
scoreboard players add #sincos.s pool.math 100000
scoreboard players set #sincos.p pool.math 200000
scoreboard players operation #sincos.s pool.math /= #sincos.p pool.math
scoreboard players operation #sincos.s pool.math *= #-1 pool.const
scoreboard players add #sincos.s pool.math 10000
scoreboard players operation #sincos.s pool.math *= #sincos.t pool.math
scoreboard players add #sincos.s pool.math 30000
scoreboard players set #sincos.p pool.math 60000
scoreboard players operation #sincos.s pool.math /= #sincos.p pool.math
scoreboard players operation #sincos.s pool.math *= #-1 pool.const
scoreboard players add #sincos.s pool.math 10000
scoreboard players operation #sincos.s pool.math *= #sincos.x pool.math
scoreboard players add #sincos.s pool.math 5000
scoreboard players operation #sincos.s pool.math /= #10000 pool.const
