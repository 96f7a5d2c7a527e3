# pool:physics/resolve/ball_ball/no_hit — the balls of this ball-ball event did not approach after all
# (pool:physics/resolve/ball_ball/collide changed nothing): remember the pair and the time, so that
# pool:physics/detect/pair does not report it again at this same time (it would for ever).
# Reads: @s (a) and pool.event_b's pool.id, #te pool.tmp. Writes: #nohit.a #nohit.b #nohit.t pool.tmp.
scoreboard players operation #nohit.a pool.tmp = @s pool.id
execute as @e[tag=pool.event_b,limit=1] run scoreboard players operation #nohit.b pool.tmp = @s pool.id
scoreboard players operation #nohit.t pool.tmp = #te pool.tmp
