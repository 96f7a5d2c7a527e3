# pool:physics/resolve/balls — @s (a) meets the ball tagged pool.event_b (b): touch, collide, then both
# start new motion phases. Reads/writes: both balls' scores; #b.* pool.tmp.
execute as @e[tag=pool.event_b,limit=1] run function pool:physics/resolve/load_b
function pool:physics/resolve/touch
tag @s add pool.touch
tag @e[tag=pool.event_b] add pool.touch
function pool:ball/collide/resolve
execute if score #hit pool.tmp matches 0 run function pool:physics/resolve/no_hit
function pool:ball/phase/start
execute as @e[tag=pool.event_b,limit=1] run function pool:physics/resolve/store_b
