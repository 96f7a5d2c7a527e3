# pool:physics/substep — from #now to the tick's end: dirty balls (all at the tick's start, then
# those of the last event) are advanced to the end along new chords; the others keep their chord,
# its start moved to #now. If the chords meet a rail, a pocket or another ball, only the balls of
# the earliest event are rewound to it and resolved, then the rest of the tick is redone.
# Reads/writes: #now #events pool.tmp, every ball's scores; temporaries #rem #step #te #best #kind
# #partner #event_rail pool.tmp. A ball at rest that was not hit keeps cx = x (its chord is a
# point) all through the tick.
scoreboard players set #rem pool.tmp 10000
scoreboard players operation #rem pool.tmp -= #now pool.tmp
tag @e[tag=pool.fresh] remove pool.fresh
execute as @e[tag=pool.ball,scores={pool.state=0..2}] run function pool:ball/trial
execute as @e[tag=pool.moving] run function pool:physics/find/ball
# the earliest of the balls' events: the minimum first, then its ball (a running minimum
# `execute as @e if score @s pool.nt < #te run ...` would take the last ball visited, since
# each execute stage runs over all contexts before `run`)
scoreboard players set #te pool.tmp 20000
scoreboard players operation #te pool.tmp < @e[tag=pool.moving] pool.nt
tag @e[tag=pool.event] remove pool.event
tag @e[tag=pool.event_b] remove pool.event_b
execute if score #te pool.tmp matches 20000 run return 0
execute as @e[tag=pool.moving] if score @s pool.nt = #te pool.tmp run function pool:physics/find/take
execute if score #kind pool.tmp matches 1 as @e[tag=pool.ball] if score @s pool.id = #partner pool.tmp run tag @s add pool.event_b
execute as @e[tag=pool.event] run function pool:ball/rewind
execute as @e[tag=pool.event_b] run function pool:ball/rewind
execute as @e[tag=pool.event,limit=1] run function pool:physics/resolve
scoreboard players operation #now pool.tmp = #te pool.tmp
execute as @e[tag=pool.event] run function pool:ball/resume
execute as @e[tag=pool.event_b] run function pool:ball/resume
function pool:physics/find/mark_stale
scoreboard players add #events pool.tmp 1
# at the cap the rest of this tick is dropped: every ball waits at the event's time
execute if score #events pool.tmp >= $max_events pool.const run return run function pool:physics/wait
execute if score #now pool.tmp matches ..9999 run function pool:physics/substep
