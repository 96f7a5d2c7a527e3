# pool:physics/resolve/ball_ball/touch/step — one Newton step of pool:physics/resolve/ball_ball/touch:
# the gap g = |r_b - r_a| - (2R + 1) (pool:physics/resolve/ball_ball/touch/gap, rounded to 1 um) and
# the closing speed c = (v_a - v_b) . n give the time g / c to move both balls by; then the next
# step, until g = 0 (or |g| = 1 twice, or four moves). #ball_ball.steps becomes -1 when touch must
# put the balls back: |g| did not shrink (or is more than 2 mm), c <= 0, or a move of more than 30 mm.
# Reads/writes: @s pool.x pool.z, #ball_ball.b.x #ball_ball.b.z #ball_ball.last #ball_ball.steps
# #cost.work pool.tmp; reads the velocities and #ball_ball.fast. Writes: #ball_ball.g #ball_ball.c
# #ball_ball.ag #ball_ball.t #ball_ball.sx #ball_ball.sz pool.tmp and the math library's temporaries.
function pool:physics/resolve/ball_ball/touch/gap
function pool:physics/resolve/ball_ball/touch/closing
scoreboard players operation #ball_ball.ag pool.tmp = #ball_ball.g pool.tmp
execute if score #ball_ball.ag pool.tmp matches ..-1 run scoreboard players operation #ball_ball.ag pool.tmp *= #-1 pool.const
execute if score #ball_ball.ag pool.tmp matches 0 run return 0
execute if score #ball_ball.ag pool.tmp matches 1 if score #ball_ball.last pool.tmp matches ..1 run return 0
execute if score #ball_ball.c pool.tmp matches ..0 run return run scoreboard players set #ball_ball.steps pool.tmp -1
execute if score #ball_ball.ag pool.tmp >= #ball_ball.last pool.tmp run return run scoreboard players set #ball_ball.steps pool.tmp -1
execute if score #ball_ball.steps pool.tmp matches 4.. run return 0
scoreboard players add #ball_ball.steps pool.tmp 1
# the event's estimate (pool:physics/events/run) covers one move; each further one is charged
execute if score #ball_ball.steps pool.tmp matches 2.. run scoreboard players add #cost.work pool.tmp 250
scoreboard players operation #ball_ball.last pool.tmp = #ball_ball.ag pool.tmp
# the move of the faster ball (#ball_ball.fast: 1 for a, 0 for b) relative to the other: along
# their relative velocity (pool:physics/resolve/ball_ball/touch/relative), or along the normal out
# of an overlap that the straight paths would take more than half a tick to leave (g < 0 and
# |g| > c / 2, #ball_ball.t = 2 |g| then: a ball squeezed between two others at one instant, whose
# time could not move): following the relative path back that far carried it millimetres into a
# third ball
scoreboard players set #ball_ball.t pool.tmp 0
execute if score #ball_ball.g pool.tmp matches ..-1 run scoreboard players operation #ball_ball.t pool.tmp = #ball_ball.ag pool.tmp
scoreboard players operation #ball_ball.t pool.tmp *= #2 pool.const
execute if score #ball_ball.t pool.tmp <= #ball_ball.c pool.tmp run function pool:physics/resolve/ball_ball/touch/relative
execute if score #ball_ball.t pool.tmp > #ball_ball.c pool.tmp run function pool:physics/resolve/ball_ball/touch/normal
execute unless score #ball_ball.sx pool.tmp matches -30000..30000 run return run scoreboard players set #ball_ball.steps pool.tmp -1
execute unless score #ball_ball.sz pool.tmp matches -30000..30000 run return run scoreboard players set #ball_ball.steps pool.tmp -1
execute if score #ball_ball.fast pool.tmp matches 1 run scoreboard players operation @s pool.x += #ball_ball.sx pool.tmp
execute if score #ball_ball.fast pool.tmp matches 1 run scoreboard players operation @s pool.z += #ball_ball.sz pool.tmp
execute if score #ball_ball.fast pool.tmp matches 0 run scoreboard players operation #ball_ball.b.x pool.tmp -= #ball_ball.sx pool.tmp
execute if score #ball_ball.fast pool.tmp matches 0 run scoreboard players operation #ball_ball.b.z pool.tmp -= #ball_ball.sz pool.tmp
function pool:physics/resolve/ball_ball/touch/step
