# pool:physics/resolve/ball_ball/touch/square — the square of |$a| < 2^16 in three parts, for
# pool:physics/resolve/ball_ball/touch/gap: with |$a| = h 256 + l, a^2 = h^2 65536 + 2 h l 256 + l^2.
# Reads: $a pool.math. Writes: #ball_ball.h (h^2) #ball_ball.m (2 h l) #ball_ball.l (l^2)
# #ball_ball.q pool.tmp.
execute if score $a pool.math matches ..-1 run scoreboard players operation $a pool.math *= #-1 pool.const
scoreboard players operation #ball_ball.q pool.tmp = $a pool.math
scoreboard players operation #ball_ball.q pool.tmp /= #256 pool.const
scoreboard players operation #ball_ball.l pool.tmp = $a pool.math
scoreboard players operation #ball_ball.l pool.tmp %= #256 pool.const
scoreboard players operation #ball_ball.m pool.tmp = #ball_ball.q pool.tmp
scoreboard players operation #ball_ball.m pool.tmp *= #ball_ball.l pool.tmp
scoreboard players operation #ball_ball.m pool.tmp *= #2 pool.const
scoreboard players operation #ball_ball.h pool.tmp = #ball_ball.q pool.tmp
scoreboard players operation #ball_ball.h pool.tmp *= #ball_ball.q pool.tmp
scoreboard players operation #ball_ball.l pool.tmp *= #ball_ball.l pool.tmp
