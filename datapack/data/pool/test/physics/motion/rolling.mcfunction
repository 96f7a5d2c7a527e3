# @batch physics_motion_rolling
# @timeout 120
# Rolling (pool:physics/motion/roll/*): a ball struck at the natural-roll height (tip 2/5 R above
# centre) rolls at once and loses mu_r g = 245.25 um/tick every tick along a straight line until it
# stops.
# Expected values from the float reference (emulator/physics): strike(Shot(0, 0.4, 0, 0.4)) gives
# v = w = 23531.9 um/tick along +x; after 20 ticks 18626.9 um/tick at x = 721587 um; it stops after
# 95.95 ticks at x = 1428946 um. Tolerances: the cue strike's 0.1 % (24 um/tick) plus 2 um/tick for
# speeds; DESIGN.md section 6's stop position, 1 mm + 0.05 % of the path, plus the strike's 0.1 %
# (2.3 mm here) for positions; the stop tick +-1.
function pool:table/setup
kill @e[tag=pool.ball]
function pool:table/rack/ball {id:0, x:300000, z:635000, item:"minecraft:white_concrete"}
function pool:api/shot {angle:0, speed:400, tip_x:0, tip_y:400, elevation:0}
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vx matches 23506..23557
await delay 1
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.state matches 2
await delay 19
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vx matches 18601..18652
execute as @e[tag=pool.ball,scores={pool.id=0}] run assert score @s pool.wx = @s pool.vx
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.x matches 718287..724887
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.z matches 635000
await delay 74
# tick 94: still rolling
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.state matches 2
await delay 3
# tick 97: stopped
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.state matches 0
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.x matches 1425111..1432781
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vx matches 0
