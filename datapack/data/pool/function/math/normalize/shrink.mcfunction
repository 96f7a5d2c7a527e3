# pool:math/normalize/shrink — divide both magnitudes by d = m/32768 + 1 so the larger is below 32768.
# Reads/writes: #normalize.nx #normalize.nz #normalize.m pool.math; temporary #normalize.d
# pool.math.
scoreboard players operation #normalize.d pool.math = #normalize.m pool.math
scoreboard players operation #normalize.d pool.math /= #32768 pool.const
scoreboard players add #normalize.d pool.math 1
scoreboard players operation #normalize.nx pool.math /= #normalize.d pool.math
scoreboard players operation #normalize.nz pool.math /= #normalize.d pool.math
