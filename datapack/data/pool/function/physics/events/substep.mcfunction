# pool:physics/events/substep — from #events.now to the tick's end: dirty balls (all at the tick's
# start, then those of the last event) are advanced to the end along new chords (pool.fresh); the
# others keep their chord, its start moved to #events.now. The balls with new chords, and those
# whose stored event involved the last event's balls (pool.stale), search their events
# (pool:physics/detect/next); the others' stored events stay valid. If the chords meet a rail, a
# pocket or another ball, only the balls of the earliest event are rewound to it and resolved, then
# the rest of the tick is redone. Each step (a trial, a ball's event search, an event) runs only
# when its estimated cost still fits in this game tick's $budget (#cost.work); else $carry pool.game
# is set and the next game tick goes on from where this one stopped (pool:physics/step). The
# searches done (pool.found) and the new chords (pool.fresh) stay tagged until the event is resolved
# or the tick ends.
# Reads/writes: #events.now #cost.work #events.count pool.tmp, $carry pool.game, every ball's
# scores; temporaries #events.rem #events.te #detect.best #events.kind #events.partner #events.rail
# pool.tmp. A ball at rest that was not hit keeps cx = x (its chord is a point) all through the
# tick.
scoreboard players set #events.rem pool.tmp 10000
scoreboard players operation #events.rem pool.tmp -= #events.now pool.tmp
execute as @e[tag=pool.dirty] run function pool:physics/events/trial
execute if entity @e[tag=pool.dirty] run return run scoreboard players set $carry pool.game 1
execute as @e[tag=pool.fresh,tag=!pool.found] run function pool:physics/detect/next
execute as @e[tag=pool.stale,tag=!pool.found] run function pool:physics/detect/next
execute if entity @e[tag=pool.fresh,tag=!pool.found] run return run scoreboard players set $carry pool.game 1
execute if entity @e[tag=pool.stale,tag=!pool.found] run return run scoreboard players set $carry pool.game 1
# the earliest of the balls' events: the minimum first, then its ball (a running minimum
# `execute as @e if score @s pool.nt < #events.te run ...` would take the last ball visited, since
# each execute stage runs over all contexts before `run`)
scoreboard players set #events.te pool.tmp 20000
scoreboard players operation #events.te pool.tmp < @e[tag=pool.moving] pool.nt
tag @e[tag=pool.event] remove pool.event
tag @e[tag=pool.event_b] remove pool.event_b
execute if score #events.te pool.tmp matches 20000 run return 0
# a guard that should never act: after 64 events at one instant the rest of the physics tick is run
# without events (pool:physics/events/finish pushes apart what that leaves overlapping) rather than
# freezing the table
execute if score #events.same pool.tmp matches 64.. run return 0
execute as @e[tag=pool.moving] if score @s pool.nt = #events.te pool.tmp run function pool:physics/events/take
function pool:physics/events/run
execute if score $carry pool.game matches 1 run return 0
execute if score #events.now pool.tmp matches ..9999 run function pool:physics/events/substep
