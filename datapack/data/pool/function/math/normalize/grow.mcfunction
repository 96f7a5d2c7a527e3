# pool:math/normalize/grow — multiply both magnitudes by k = 32767/m so the larger lies in 16384..32767.
# Reads/writes: #nx #nz #m pool.math; temporary #d pool.math.
scoreboard players operation #d pool.math = #32767 pool.const
scoreboard players operation #d pool.math /= #m pool.math
scoreboard players operation #nx pool.math *= #d pool.math
scoreboard players operation #nz pool.math *= #d pool.math
