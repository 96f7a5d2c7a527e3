# pool:physics/substep — move every ball from #now to the tick's end; if an event happens on the
# way, rewind everything to the earliest one, resolve it and continue from there (recursively).
# Reads/writes: #now #events pool.tmp, every ball's scores; temporaries #rem #step #best #kind.
scoreboard players set #rem pool.tmp 10000
scoreboard players operation #rem pool.tmp -= #now pool.tmp
scoreboard players operation #step pool.tmp = #rem pool.tmp
execute as @e[tag=pool.ball,scores={pool.state=0..2}] run function pool:ball/trial
scoreboard players set #best pool.tmp 10001
scoreboard players set #kind pool.tmp 0
tag @e[tag=pool.event] remove pool.event
tag @e[tag=pool.event_b] remove pool.event_b
execute as @e[tag=pool.moving] run function pool:physics/find/ball
execute if score #best pool.tmp matches 10001 run return 0
# the event's time: best / 10000 of the remaining interval
scoreboard players operation #step pool.tmp = #best pool.tmp
scoreboard players operation #step pool.tmp *= #rem pool.tmp
scoreboard players operation #step pool.tmp /= #10000 pool.const
execute as @e[tag=pool.ball,scores={pool.state=0..2}] run function pool:ball/rewind
execute as @e[tag=pool.event,limit=1] run function pool:physics/resolve
scoreboard players operation #now pool.tmp += #step pool.tmp
scoreboard players add #events pool.tmp 1
# at the cap the rest of this tick is dropped: the balls wait at the event (never pass through)
execute if score #events pool.tmp >= $max_events pool.const run return 0
execute if score #now pool.tmp matches ..9999 run function pool:physics/substep
