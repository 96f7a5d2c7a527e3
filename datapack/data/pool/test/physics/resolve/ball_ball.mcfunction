# @batch physics_resolve_ball_ball
# @timeout 10
# Ball-ball collision (pool:physics/resolve/ball_ball/collide, through the tick's swept events):
# head on, the cue ball stops and the object ball takes its speed; hit at a 45 degree cut, the two
# leave at right angles with the speed split evenly.
# Expected values from the float reference (emulator/physics): strike(Shot(0, 1.5)) gives
# v0 = 115400.3 um/tick; simulate_ticks one tick later: head on (object ball 2R + 1 mm ahead), cue
# ball at rest, object ball vx = 110495.3 um/tick at x = 1170098 um; for the cut (object ball at
# 2R (cos 45, sin 45) + (1 mm, 0) from the cue ball), cue ball v = (54243.3, -54237.4), object ball
# v = (54241.0, 54240.6) um/tick: a 90 degree split. Tolerances: the cue strike's 0.1 % (115
# um/tick) plus DESIGN.md section 6's 0.1 degree on the object ball's direction (95 um/tick here)
# and 1e-3 of the energy, rounded up to 250 um/tick; positions 1 mm + 0.1 % of the path. The
# scores are read when the physics tick is complete ($carry pool.game 0: a collision's tick may
# finish in the next game tick), and the second rack starts on a finished one.
function pool:table/setup
kill @e[tag=pool.ball]
function pool:table/rack/ball {id:0, x:1000000, z:635000, item:"minecraft:white_concrete"}
function pool:table/rack/ball {id:1, x:1059150, z:635000, item:"minecraft:yellow_concrete"}
function pool:api/shot {angle:0, speed:1500, tip_x:0, tip_y:0, elevation:0}
await delay 1
await score $carry pool.game matches 0
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vx matches -250..250
assert score @e[tag=pool.ball,scores={pool.id=1},limit=1] pool.vx matches 110245..110745
assert score @e[tag=pool.ball,scores={pool.id=1},limit=1] pool.vz matches 0
assert score @e[tag=pool.ball,scores={pool.id=1},limit=1] pool.x matches 1168928..1171268

# the cut: a fresh rack of two
kill @e[tag=pool.ball]
scoreboard players set $resting pool.game 1
function pool:table/rack/ball {id:0, x:1000000, z:635000, item:"minecraft:white_concrete"}
function pool:table/rack/ball {id:1, x:1041411, z:675411, item:"minecraft:yellow_concrete"}
function pool:api/shot {angle:0, speed:1500, tip_x:0, tip_y:0, elevation:0}
await delay 1
await score $carry pool.game matches 0
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vx matches 53993..54493
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vz matches -54487..-53987
assert score @e[tag=pool.ball,scores={pool.id=1},limit=1] pool.vx matches 53991..54491
assert score @e[tag=pool.ball,scores={pool.id=1},limit=1] pool.vz matches 53990..54490
