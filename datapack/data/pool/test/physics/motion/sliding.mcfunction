# @batch physics_motion_sliding
# @timeout 20
# Sliding (pool:physics/motion/slide/*): a centre-hit ball slides, cloth friction takes mu_s g =
# 4905 um/tick off its speed every tick, and in the tick where the slip ends it snaps to rolling at
# (5 v0 + 2 w0)/7.
# Expected values from the float reference (emulator/physics): strike(Shot(0, 1.5)) gives
# v0 = 115400.3 um/tick, w0 = 0; the slide lasts 2 v0 / (7 mu_s g) = 6.72 ticks, then the ball rolls
# at 82428.8 less 0.28 tick of rolling (mu_r g = 245.25 um/tick^2): 82360.6 after tick 7, at
# x = 987809 um. Tolerances: the cue strike's 0.1 % (DESIGN.md section 6) carried along, 2 um/tick for
# the per-tick deceleration, 1 mm + 0.1 % of the path for the position.
function pool:table/setup
kill @e[tag=pool.ball]
function pool:table/rack/ball {id:0, x:300000, z:635000, item:"minecraft:white_concrete"}
scoreboard objectives add pool.test dummy
function pool:api/shot {angle:0, speed:1500, tip_x:0, tip_y:0, elevation:0}
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.state matches 1
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vx matches 115285..115516
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vz matches 0
scoreboard players operation #sliding.v0 pool.test = @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vx
await delay 1
# one tick of sliding: 4905 um/tick slower
scoreboard players operation #sliding.v0 pool.test -= @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vx
assert score #sliding.v0 pool.test matches 4903..4907
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.state matches 1
await delay 5
# tick 6: still sliding (the slide ends at 6.72)
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.state matches 1
await delay 1
# tick 7: rolling, v = w, at the closed-form rolling velocity
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.state matches 2
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vx matches 82276..82445
execute as @e[tag=pool.ball,scores={pool.id=0}] run assert score @s pool.wx = @s pool.vx
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.x matches 986121..989497
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.z matches 635000
