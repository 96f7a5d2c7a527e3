# pool:physics/resolve/ball_ball/touch — bring @s (a) and b (#ball_ball.b.*) to touching, |r_b - r_a|
# = 2R + 1 um (0.5 to 1.5 um after rounding: near a tangent every um of gap turns the contact normal,
# 0.06 degrees at 89 degrees), by moving the faster one along their relative velocity (the other
# stays: a pair moving together is not carried along its common velocity, a ball at rest stays on
# its spot): the sweep's chords miss the curved sliding paths by up to 0.6 mm, so the balls can
# meet there a little apart or overlapping, which would tilt the contact normal. The time solves
# |r_b - r_a| = 2R + 1 for straight paths by Newton's method (pool:physics/resolve/ball_ball/touch/step):
# the distance is convex in time, so from a gap the steps close it from one side, and from an
# overlap the first step lands on that side; a nearly tangent pair may move a few mm, which is how
# far along its path the contact really was. When the paths miss on straight lines (the gap
# stops shrinking), the pair stops approaching or a step would move a ball more than 30 mm, both
# balls go back to where they were.
# Reads/writes: @s pool.x pool.z, #ball_ball.b.x #ball_ball.b.z pool.tmp; reads @s pool.vx pool.vz,
# #ball_ball.b.vx #ball_ball.b.vz.
# Temporaries #ball_ball.a0x #ball_ball.a0z #ball_ball.b0x #ball_ball.b0z #ball_ball.last
# #ball_ball.steps #ball_ball.g #ball_ball.c #ball_ball.fast #ball_ball.fa #ball_ball.fb pool.tmp, those of touch/step and the math library's.
scoreboard players operation #ball_ball.a0x pool.tmp = @s pool.x
scoreboard players operation #ball_ball.a0z pool.tmp = @s pool.z
scoreboard players operation #ball_ball.b0x pool.tmp = #ball_ball.b.x pool.tmp
scoreboard players operation #ball_ball.b0z pool.tmp = #ball_ball.b.z pool.tmp
scoreboard players set #ball_ball.last pool.tmp 2001
scoreboard players set #ball_ball.steps pool.tmp 0
# the faster ball (|vx| + |vz|; a on a tie) moves, relative to the other: a pair moving together
# closes its gap without being carried along its common velocity
scoreboard players operation #ball_ball.fa pool.tmp = @s pool.vx
execute if score #ball_ball.fa pool.tmp matches ..-1 run scoreboard players operation #ball_ball.fa pool.tmp *= #-1 pool.const
scoreboard players operation #ball_ball.fb pool.tmp = @s pool.vz
execute if score #ball_ball.fb pool.tmp matches ..-1 run scoreboard players operation #ball_ball.fb pool.tmp *= #-1 pool.const
scoreboard players operation #ball_ball.fa pool.tmp += #ball_ball.fb pool.tmp
scoreboard players operation #ball_ball.fb pool.tmp = #ball_ball.b.vx pool.tmp
execute if score #ball_ball.fb pool.tmp matches ..-1 run scoreboard players operation #ball_ball.fb pool.tmp *= #-1 pool.const
scoreboard players operation #ball_ball.fa pool.tmp -= #ball_ball.fb pool.tmp
scoreboard players operation #ball_ball.fb pool.tmp = #ball_ball.b.vz pool.tmp
execute if score #ball_ball.fb pool.tmp matches ..-1 run scoreboard players operation #ball_ball.fb pool.tmp *= #-1 pool.const
scoreboard players operation #ball_ball.fa pool.tmp -= #ball_ball.fb pool.tmp
scoreboard players set #ball_ball.fast pool.tmp 0
execute if score #ball_ball.fa pool.tmp matches 0.. run scoreboard players set #ball_ball.fast pool.tmp 1
function pool:physics/resolve/ball_ball/touch/step
execute unless score #ball_ball.steps pool.tmp matches -1 run return 0
scoreboard players operation @s pool.x = #ball_ball.a0x pool.tmp
scoreboard players operation @s pool.z = #ball_ball.a0z pool.tmp
scoreboard players operation #ball_ball.b.x pool.tmp = #ball_ball.b0x pool.tmp
scoreboard players operation #ball_ball.b.z pool.tmp = #ball_ball.b0z pool.tmp
