# pool:physics/resolve/ball_ball/no_hit — the balls of this ball-ball event did not approach after
# all (pool:physics/resolve/ball_ball/collide changed nothing): remember the pair and the time, so
# that pool:physics/detect/pair does not report it again at this same time (it would for ever).
# Reads: @s (a) and pool.event_b's pool.id, #events.te pool.tmp. Writes: #ball_ball.nohit.a
# #ball_ball.nohit.b #ball_ball.nohit.t pool.tmp.
scoreboard players operation #ball_ball.nohit.a pool.tmp = @s pool.id
execute as @e[tag=pool.event_b,limit=1] run scoreboard players operation #ball_ball.nohit.b pool.tmp = @s pool.id
scoreboard players operation #ball_ball.nohit.t pool.tmp = #events.te pool.tmp
