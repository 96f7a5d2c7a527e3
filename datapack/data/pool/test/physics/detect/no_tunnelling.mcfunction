# @batch physics_detect_no_tunnelling
# @timeout 10
# The swept event search (pool:physics/detect/*): at 10 m/s a ball moves 0.5 m, 8.75 diameters, in
# one tick; an object ball 7 diameters ahead lies on its chord and is hit within the first tick,
# not passed through.
# Expected from the float reference (poolgame/physics): strike(Shot(0, 6.5)) gives 500067.8
# um/tick; simulate_ticks one tick later: the cue ball at x = 978089 um moving at 1530.7 um/tick,
# the object ball at x = 1189765 um moving at 495162.8 um/tick. Tolerances: the strike's 0.1 %
# (500 um/tick) for speeds, 1 mm + 0.1 % of the path (0.5 m) for positions, rounded up to 1.6 mm.
function pool:table/setup
kill @e[tag=pool.ball]
function pool:table/rack/ball {id:0, x:635000, z:635000, item:"minecraft:white_concrete"}
function pool:table/rack/ball {id:1, x:1035000, z:635000, item:"minecraft:yellow_concrete"}
function pool:api/shot {angle:0, speed:6500, tip_x:0, tip_y:0, elevation:0}
await delay 1
assert score @e[tag=pool.ball,scores={pool.id=1},limit=1] pool.vx matches 494663..495663
assert score @e[tag=pool.ball,scores={pool.id=1},limit=1] pool.x matches 1188165..1191365
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vx matches 1031..2031
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.x matches 976489..979689
