# @batch physics_display_place
# @timeout 10
# @dummy
# The displays (pool:physics/display/*): each ball's item_display stands at the table corner (where
# pool:table/setup ran) plus the ball's centre in mm, R = 28 mm above the cloth; a pocketed ball's
# goes to the ball return, the N-th one pocketed 60 N mm along the table's z = 0 side and 120 mm
# outside it.
function pool:table/setup
# the cue ball on the head spot (635, 635) mm, the apex ball on the foot spot (1905, 635) mm
execute positioned ~0.635 ~0.028 ~0.635 run assert entity @e[tag=pool.ball,scores={pool.id=0},distance=..0.0001]
execute positioned ~1.905 ~0.028 ~0.635 run assert entity @e[tag=pool.ball,scores={pool.id=1},distance=..0.0001]
# a ball sent into the corner pocket at (0, 0)
kill @e[tag=pool.ball]
function pool:table/rack/ball {id:0, x:300000, z:300000, item:"minecraft:white_concrete"}
function pool:api/shot {angle:-13500, speed:2000, tip_x:0, tip_y:0, elevation:0}
await score $pocketed pool.game matches 1
execute positioned ~0.060 ~0.028 ~-0.120 run assert entity @e[tag=pool.ball,scores={pool.id=0},distance=..0.0001]
