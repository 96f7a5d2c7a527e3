# @batch physics_events_at_rest
# @timeout 120
# @dummy
# The table-at-rest flag: $resting pool.game is 0 from the strike until no ball moves, then 1
# (with a chat message); a shot while the balls move is refused and changes nothing.
# Expected from the float reference (emulator/physics): strike(Shot(0, 0.4, 0, 0.4)) rolls at once
# at 23531.9 um/tick and stops after 95.95 ticks (+-1 tick: DESIGN.md section 6's transition tick).
function pool:table/setup
kill @e[tag=pool.ball]
function pool:table/rack/ball {id:0, x:300000, z:635000, item:"minecraft:white_concrete"}
assert score $resting pool.game matches 1
function pool:api/shot {angle:0, speed:400, tip_x:0, tip_y:400, elevation:0}
assert score $resting pool.game matches 0
await delay 10
function pool:api/shot {angle:9000, speed:6000, tip_x:0, tip_y:0, elevation:0}
assert chat "^Pool: shot refused: the balls are still moving$"
assert score $shot.angle pool.game matches 0
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vz matches 0
await delay 84
# tick 94
assert score $resting pool.game matches 0
assert not chat "the table is at rest"
await delay 3
# tick 97: at rest
assert score $resting pool.game matches 1
assert chat "^Pool: the table is at rest$"
assert not entity @e[tag=pool.ball,scores={pool.state=1..3}]
