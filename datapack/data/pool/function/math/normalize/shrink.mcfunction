# pool:math/normalize/shrink — divide both magnitudes by d = m/32768 + 1 so the larger is below 32768.
# Reads/writes: #nx #nz #m pool.math; temporary #d pool.math.
scoreboard players operation #d pool.math = #m pool.math
scoreboard players operation #d pool.math /= #32768 pool.const
scoreboard players add #d pool.math 1
scoreboard players operation #nx pool.math /= #d pool.math
scoreboard players operation #nz pool.math /= #d pool.math
