# pool:physics/resolve/ball_ball — @s (a) meets the ball tagged pool.event_b (b): the event moves to
# the time they touch (meet), the rest of the gap is closed (touch), collide, then both start new
# motion phases. Reads/writes: both balls' scores, #events.te; #ball_ball.b.* pool.tmp.
execute as @e[tag=pool.event_b,limit=1] run function pool:physics/resolve/ball_ball/load_b
function pool:physics/resolve/ball_ball/meet
function pool:physics/resolve/ball_ball/touch
tag @s add pool.touch
tag @e[tag=pool.event_b] add pool.touch
function pool:physics/resolve/ball_ball/collide
execute if score #ball_ball.hit pool.tmp matches 0 run function pool:physics/resolve/ball_ball/no_hit
function pool:physics/motion/start
execute as @e[tag=pool.event_b,limit=1] run function pool:physics/resolve/ball_ball/store_b
