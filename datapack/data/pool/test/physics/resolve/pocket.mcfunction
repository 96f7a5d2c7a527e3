# @batch physics_resolve_pocket
# @timeout 10
# @dummy
# Pockets (pool:physics/detect/sweep/pocket, pool:physics/resolve/pocket): a ball sent into a corner
# pocket leaves play (pool.state 3), $pocketed counts it, $last_pocketed names it, the players are
# told. The dummy player is there to receive the chat message, as in the game.
# Expected from the float reference (emulator/physics): strike(Shot(-135 degrees, 2.0)) from
# (300, 300) mm slides at 108800 um/tick per axis towards the corner at (0, 0); simulate_ticks
# pockets it in tick 3 (+-1 tick).
function pool:table/setup
kill @e[tag=pool.ball]
function pool:table/rack/ball {id:0, x:300000, z:300000, item:"minecraft:white_concrete"}
function pool:table/rack/ball {id:5, x:1270000, z:900000, item:"minecraft:orange_concrete"}
function pool:api/shot {angle:-13500, speed:2000, tip_x:0, tip_y:0, elevation:0}
await delay 1
assert score $pocketed pool.game matches 0
await score $pocketed pool.game matches 1
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.state matches 3
assert score $last_pocketed pool.game matches 0
# the message names the ball with a score text component: "Pool: ball 0 is pocketed"
assert chat "^Pool: ball .*is pocketed$"
assert score @e[tag=pool.ball,scores={pool.id=5},limit=1] pool.state matches 0
assert score @e[tag=pool.ball,scores={pool.id=5},limit=1] pool.x matches 1270000
