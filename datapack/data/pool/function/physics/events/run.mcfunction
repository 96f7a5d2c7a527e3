# pool:physics/events/run — resolve the earliest event (time #events.te, on the moving balls tagged
# by pool:physics/events/take) when its estimated cost still fits in this game tick's $budget (or it
# is the game tick's first work), else carry the physics tick over: its balls are rewound to
# #events.te, resolved, and go on from there.
# Reads/writes: #events.te #events.kind #events.partner #events.now #cost.work #events.same
# pool.tmp, $carry pool.game, the event's balls; tags pool.event pool.event_b, pool.settled (removed
# from the event's balls).
execute if score #events.kind pool.tmp matches 1 as @e[tag=pool.ball] if score @s pool.id = #events.partner pool.tmp run tag @s add pool.event_b
# the resolution and restarts about 1020 commands (1640 with a ball-ball contact's move in time and
# first Newton step: pool:physics/resolve/ball_ball/touch/step charges each further one), plus each
# ball's rewind from its saved time
scoreboard players set #cost.next pool.tmp 1020
execute if score #events.kind pool.tmp matches 1 run scoreboard players set #cost.next pool.tmp 1640
execute as @e[tag=pool.event] run function pool:physics/events/cost/rewind
# a cushion rewinds its ball once more, to where its path crosses the rail line (pool:physics/resolve/cushion/cross)
execute if score #events.kind pool.tmp matches 2 as @e[tag=pool.event] run function pool:physics/events/cost/rewind
execute as @e[tag=pool.event_b] run function pool:physics/events/cost/rewind
# a ball-ball contact rewinds both balls once more, to the time they touch (pool:physics/resolve/ball_ball/meet)
execute if score #events.kind pool.tmp matches 1 as @e[tag=pool.event] run function pool:physics/events/cost/rewind
execute if score #events.kind pool.tmp matches 1 as @e[tag=pool.event_b] run function pool:physics/events/cost/rewind
scoreboard players operation #cost.next pool.tmp += #cost.work pool.tmp
# (the first work of a game tick always runs, so that a small $budget slows the table, never stops it)
execute if score #cost.work pool.tmp matches 1.. if score #cost.next pool.tmp > $budget pool.const run return run scoreboard players set $carry pool.game 1
scoreboard players operation #cost.work pool.tmp = #cost.next pool.tmp
# the searches of this sub-step are used up (a game tick that carried the event over skips them)
tag @e[tag=pool.found] remove pool.found
tag @e[tag=pool.fresh] remove pool.fresh
tag @e[tag=pool.event] remove pool.settled
tag @e[tag=pool.event_b] remove pool.settled
execute as @e[tag=pool.event] run function pool:physics/events/rewind
execute as @e[tag=pool.event_b] run function pool:physics/events/rewind
execute as @e[tag=pool.event,limit=1] run function pool:physics/resolve
# events at one same instant, one after another (#events.same): a guard against a pair found again
# and again
execute if score #events.te pool.tmp = #events.now pool.tmp run scoreboard players add #events.same pool.tmp 1
execute unless score #events.te pool.tmp = #events.now pool.tmp run scoreboard players set #events.same pool.tmp 0
scoreboard players operation #events.now pool.tmp = #events.te pool.tmp
execute as @e[tag=pool.event] run function pool:physics/events/resume
execute as @e[tag=pool.event_b] run function pool:physics/events/resume
function pool:physics/detect/mark_stale
scoreboard players add #events.count pool.tmp 1
