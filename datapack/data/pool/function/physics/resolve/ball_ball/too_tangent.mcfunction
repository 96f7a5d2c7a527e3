# pool:physics/resolve/ball_ball/too_tangent — returns 1 when a ball of the pair is faster than 8
# times the closing speed c, so that pool:physics/resolve/ball_ball/touch would move it more than 8
# |g|: tests |vx + vz| and |vx - vz| (their maximum is |vx| + |vz| >= |v|) of @s and of b against 8
# c.
# Reads: @s pool.vx pool.vz, #ball_ball.b.vx #ball_ball.b.vz #ball_ball.c pool.tmp. Writes:
# #ball_ball.k #ball_ball.nk #ball_ball.v1 #ball_ball.v2 pool.tmp.
scoreboard players set #ball_ball.k pool.tmp 8
scoreboard players operation #ball_ball.k pool.tmp *= #ball_ball.c pool.tmp
scoreboard players operation #ball_ball.nk pool.tmp = #ball_ball.k pool.tmp
scoreboard players operation #ball_ball.nk pool.tmp *= #-1 pool.const
scoreboard players operation #ball_ball.v1 pool.tmp = @s pool.vx
scoreboard players operation #ball_ball.v1 pool.tmp += @s pool.vz
scoreboard players operation #ball_ball.v2 pool.tmp = @s pool.vx
scoreboard players operation #ball_ball.v2 pool.tmp -= @s pool.vz
execute unless score #ball_ball.v1 pool.tmp <= #ball_ball.k pool.tmp run return 1
execute unless score #ball_ball.v1 pool.tmp >= #ball_ball.nk pool.tmp run return 1
execute unless score #ball_ball.v2 pool.tmp <= #ball_ball.k pool.tmp run return 1
execute unless score #ball_ball.v2 pool.tmp >= #ball_ball.nk pool.tmp run return 1
scoreboard players operation #ball_ball.v1 pool.tmp = #ball_ball.b.vx pool.tmp
scoreboard players operation #ball_ball.v1 pool.tmp += #ball_ball.b.vz pool.tmp
scoreboard players operation #ball_ball.v2 pool.tmp = #ball_ball.b.vx pool.tmp
scoreboard players operation #ball_ball.v2 pool.tmp -= #ball_ball.b.vz pool.tmp
execute unless score #ball_ball.v1 pool.tmp <= #ball_ball.k pool.tmp run return 1
execute unless score #ball_ball.v1 pool.tmp >= #ball_ball.nk pool.tmp run return 1
execute unless score #ball_ball.v2 pool.tmp <= #ball_ball.k pool.tmp run return 1
execute unless score #ball_ball.v2 pool.tmp >= #ball_ball.nk pool.tmp run return 1
return 0
