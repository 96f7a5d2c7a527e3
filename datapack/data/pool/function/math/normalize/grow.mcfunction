# pool:math/normalize/grow — multiply both magnitudes by k = 32767/m so the larger lies in 16384..32767.
# Reads/writes: #normalize.nx #normalize.nz #normalize.m pool.math; temporary #normalize.d
# pool.math.
scoreboard players operation #normalize.d pool.math = #32767 pool.const
scoreboard players operation #normalize.d pool.math /= #normalize.m pool.math
scoreboard players operation #normalize.nx pool.math *= #normalize.d pool.math
scoreboard players operation #normalize.nz pool.math *= #normalize.d pool.math
