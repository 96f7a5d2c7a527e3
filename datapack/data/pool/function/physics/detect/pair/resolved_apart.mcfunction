# pool:physics/detect/pair/resolved_apart — returns 1 when a (#pair.a.id) and b (@s) are the pair
# whose resolution at #events.now found them not approaching
# (pool:physics/resolve/ball_ball/no_hit), else 0.
# Reads: #pair.a.id #events.now #ball_ball.nohit.a #ball_ball.nohit.b #ball_ball.nohit.t pool.tmp,
# @s pool.id.
execute unless score #ball_ball.nohit.t pool.tmp = #events.now pool.tmp run return 0
execute if score #pair.a.id pool.tmp = #ball_ball.nohit.a pool.tmp if score @s pool.id = #ball_ball.nohit.b pool.tmp run return 1
execute if score #pair.a.id pool.tmp = #ball_ball.nohit.b pool.tmp if score @s pool.id = #ball_ball.nohit.a pool.tmp run return 1
return 0
