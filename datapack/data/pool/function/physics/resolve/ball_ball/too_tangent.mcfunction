# pool:physics/resolve/ball_ball/too_tangent — returns 1 when a ball of the pair is faster than 8 times the
# closing speed c, so that pool:physics/resolve/ball_ball/touch would move it more than 8 |g|: tests
# |vx + vz| and |vx - vz| (their maximum is |vx| + |vz| >= |v|) of @s and of b against 8 c.
# Reads: @s pool.vx pool.vz, #b.vx #b.vz #c pool.tmp. Writes: #k #nk #v1 #v2 pool.tmp.
scoreboard players set #k pool.tmp 8
scoreboard players operation #k pool.tmp *= #c pool.tmp
scoreboard players operation #nk pool.tmp = #k pool.tmp
scoreboard players operation #nk pool.tmp *= #-1 pool.const
scoreboard players operation #v1 pool.tmp = @s pool.vx
scoreboard players operation #v1 pool.tmp += @s pool.vz
scoreboard players operation #v2 pool.tmp = @s pool.vx
scoreboard players operation #v2 pool.tmp -= @s pool.vz
execute unless score #v1 pool.tmp <= #k pool.tmp run return 1
execute unless score #v1 pool.tmp >= #nk pool.tmp run return 1
execute unless score #v2 pool.tmp <= #k pool.tmp run return 1
execute unless score #v2 pool.tmp >= #nk pool.tmp run return 1
scoreboard players operation #v1 pool.tmp = #b.vx pool.tmp
scoreboard players operation #v1 pool.tmp += #b.vz pool.tmp
scoreboard players operation #v2 pool.tmp = #b.vx pool.tmp
scoreboard players operation #v2 pool.tmp -= #b.vz pool.tmp
execute unless score #v1 pool.tmp <= #k pool.tmp run return 1
execute unless score #v1 pool.tmp >= #nk pool.tmp run return 1
execute unless score #v2 pool.tmp <= #k pool.tmp run return 1
execute unless score #v2 pool.tmp >= #nk pool.tmp run return 1
return 0
