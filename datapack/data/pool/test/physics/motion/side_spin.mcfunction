# @batch physics_motion_side_spin
# @timeout 40
# Side-spin decay (pool:physics/motion/spin/advance): side spin wy = R omega_y loses (5/2) mu_sp g =
# 778.67 um/tick every tick (errata) until it is gone, whatever the ball's phase; it does not bend
# the path.
# Expected values from the float reference (emulator/physics): strike(Shot(0, 0.3, 0.3, 0)) gives
# v = 19674.4 um/tick along +x and wy = 14755.8 um/tick; the spin lasts 14755.8 / 778.67 = 18.95
# ticks. Tolerances: the cue strike's 0.5 % on spin (74 um/tick), 1 um/tick on the per-tick decay
# (the pack rounds 778.67 to 779).
function pool:table/setup
kill @e[tag=pool.ball]
function pool:table/rack/ball {id:0, x:300000, z:635000, item:"minecraft:white_concrete"}
scoreboard objectives add pool.test dummy
function pool:api/shot {angle:0, speed:300, tip_x:300, tip_y:0, elevation:0}
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.wy matches 14682..14830
scoreboard players operation #side_spin.wy0 pool.test = @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.wy
await delay 1
scoreboard players operation #side_spin.wy0 pool.test -= @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.wy
assert score #side_spin.wy0 pool.test matches 778..780
await delay 17
# tick 18: some spin left (14755.8 - 18 x 778.67 = 739.8)
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.wy matches 1..
await delay 1
# tick 19: gone, while the ball still rolls (it stops near tick 58)
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.wy matches 0
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.state matches 2
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.z matches 635000
