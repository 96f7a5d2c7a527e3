# @batch physics_break
# @timeout 400
# @dummy
# The break through the public API: a racked table (pool:table/setup), the cue ball struck at full
# power (6.5 m/s) at the apex ball; the table comes to rest with every ball in play inside the
# cushions and every pocketed ball counted.
# From the models (emulator/physics): a ball in play keeps its centre at least R = 28575 um from
# each cushion line, so R <= x <= L - R = 2511425 and R <= z <= W - R = 1241425 (um); a break
# settles in about 10 s (200 ticks), well within the timeout.
function pool:table/setup
scoreboard objectives add pool.test dummy
function pool:api/shot {angle:0, speed:6500, tip_x:0, tip_y:0, elevation:0}
assert score $resting pool.game matches 0
await score $resting pool.game matches 1
assert not entity @e[tag=pool.ball,scores={pool.state=1..2}]
assert not entity @e[tag=pool.ball,scores={pool.state=0,pool.x=..28574}]
assert not entity @e[tag=pool.ball,scores={pool.state=0,pool.x=2511426..}]
assert not entity @e[tag=pool.ball,scores={pool.state=0,pool.z=..28574}]
assert not entity @e[tag=pool.ball,scores={pool.state=0,pool.z=1241426..}]
execute store result score #break.balls pool.test if entity @e[tag=pool.ball]
assert score #break.balls pool.test matches 16
execute store result score #break.pocketed pool.test if entity @e[tag=pool.ball,scores={pool.state=3}]
assert score #break.pocketed pool.test = $pocketed pool.game
assert chat "^Pool: the table is at rest$"
