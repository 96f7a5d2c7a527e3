# pool:physics/detect/pair/contact — swept contact test of ball @s (b) with the ball tagged
# pool.self (a), after the cheap test of their chord boxes: returns 1 with the contact's tick time
# in #detect.t, or 0 (no contact, or a touching pair that does not approach within the tick:
# pool:physics/detect/pair/recontact).
# Reads: #pair.a.id #pair.a.lx #pair.a.hx #pair.a.lz #pair.a.hz #detect.cap pool.tmp (a's box), @s
# box and chord (a ball at rest has cx = x). Writes: #detect.t #cost.work (the exact test's cost)
# #detect.abort pool.tmp; both chords' starts moved to #events.now; the sweep's temporaries.
execute if score @s pool.lx > #pair.a.hx pool.tmp run return 0
execute if score @s pool.hx < #pair.a.lx pool.tmp run return 0
execute if score @s pool.lz > #pair.a.hz pool.tmp run return 0
execute if score @s pool.hz < #pair.a.lz pool.tmp run return 0
# the exact test costs about 220 commands with the touching tests, 130 more when its unit vector
# is not the last one (pool:physics/detect/sweep/unit): past #detect.cap the search is dropped
# (pool:physics/detect/next)
execute if score #cost.work pool.tmp > #detect.cap pool.tmp run scoreboard players set #detect.abort pool.tmp 1
execute if score #detect.abort pool.tmp matches 1 run return 0
scoreboard players add #cost.work pool.tmp 220
execute as @e[tag=pool.self] run function pool:physics/detect/chord/as_a
execute if entity @s[tag=pool.moving] run function pool:physics/detect/chord/start
scoreboard players operation #sweep.b.bx pool.tmp = @s pool.cx
scoreboard players operation #sweep.b.bz pool.tmp = @s pool.cz
scoreboard players operation #sweep.b.ex pool.tmp = @s pool.x
scoreboard players operation #sweep.b.ez pool.tmp = @s pool.z
function pool:physics/detect/sweep/pair
execute if score #sweep.f pool.tmp matches 10001 run return 0
function pool:physics/detect/absolute
# an immediate contact (at #events.now: the fraction 0, or one small enough to round to it) that
# does not approach is no event at once: resolving it would change nothing and find it again at
# once, for ever; it may still approach later in the tick (pool:physics/detect/pair/recontact)
execute unless score #detect.t pool.tmp = #events.now pool.tmp run return 1
function pool:physics/detect/pair/separating
execute if score #pair.s pool.tmp matches 1.. unless function pool:physics/detect/pair/resolved_apart run return 1
return run function pool:physics/detect/pair/recontact
