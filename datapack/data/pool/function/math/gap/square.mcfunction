# pool:math/gap/square — the square of |$a| < 2^16 in three parts, for
# pool:math/gap: with |$a| = h 256 + l, a^2 = h^2 65536 + 2 h l 256 + l^2.
# Reads: $a pool.math. Writes: #gap.h (h^2) #gap.m (2 h l) #gap.l (l^2)
# #gap.q pool.math.
execute if score $a pool.math matches ..-1 run scoreboard players operation $a pool.math *= #-1 pool.const
scoreboard players operation #gap.q pool.math = $a pool.math
scoreboard players operation #gap.q pool.math /= #256 pool.const
scoreboard players operation #gap.l pool.math = $a pool.math
scoreboard players operation #gap.l pool.math %= #256 pool.const
scoreboard players operation #gap.m pool.math = #gap.q pool.math
scoreboard players operation #gap.m pool.math *= #gap.l pool.math
scoreboard players operation #gap.m pool.math *= #2 pool.const
scoreboard players operation #gap.h pool.math = #gap.q pool.math
scoreboard players operation #gap.h pool.math *= #gap.q pool.math
scoreboard players operation #gap.l pool.math *= #gap.l pool.math
