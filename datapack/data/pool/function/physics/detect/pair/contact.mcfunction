# pool:physics/detect/pair/contact — swept contact test of ball @s (b) with the ball tagged pool.self
# (a), after the cheap test of their chord boxes: returns 1 with the contact's tick time in #t, or
# 0 (no contact, or a touching pair that does not approach: pool:physics/detect/pair/touching).
# Reads: #a.id #a.lx #a.hx #a.lz #a.hz #find_cap pool.tmp (a's box), @s box and chord (a ball at
# rest has cx = x). Writes: #t #work (the exact test's cost) #abort pool.tmp; both chords' starts
# moved to #now; the sweep's temporaries.
execute if score @s pool.lx > #a.hx pool.tmp run return 0
execute if score @s pool.hx < #a.lx pool.tmp run return 0
execute if score @s pool.lz > #a.hz pool.tmp run return 0
execute if score @s pool.hz < #a.lz pool.tmp run return 0
# the exact test costs about 220 commands with the touching tests, 130 more when its unit vector
# is not the last one (pool:physics/detect/sweep/unit): past #find_cap the search is dropped
# (pool:physics/detect/next)
execute if score #work pool.tmp > #find_cap pool.tmp run scoreboard players set #abort pool.tmp 1
execute if score #abort pool.tmp matches 1 run return 0
scoreboard players add #work pool.tmp 220
execute as @e[tag=pool.self] run function pool:physics/detect/chord/as_a
execute if entity @s[tag=pool.moving] run function pool:physics/detect/chord/start
scoreboard players operation #b.bx pool.tmp = @s pool.cx
scoreboard players operation #b.bz pool.tmp = @s pool.cz
scoreboard players operation #b.ex pool.tmp = @s pool.x
scoreboard players operation #b.ez pool.tmp = @s pool.z
function pool:physics/detect/sweep/pair
execute if score #f pool.tmp matches 10001 run return 0
function pool:physics/detect/absolute
# an immediate contact (at #now: the fraction 0, or one small enough to round to it) that does not
# approach is no event: resolving it would change nothing and find it again at once, for ever
execute if score #t pool.tmp = #now pool.tmp if function pool:physics/detect/pair/resolved_apart run return run function pool:physics/detect/pair/touching
execute if score #t pool.tmp = #now pool.tmp if function pool:physics/detect/pair/separating run return run function pool:physics/detect/pair/touching
return 1
