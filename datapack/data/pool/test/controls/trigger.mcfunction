# @batch controls_trigger
# @timeout 10
# @dummy
# The player controls (pool:controls/*): a player aims with the view (yaw -90 faces east, the
# table's +x) and sets the power with "/trigger pool.power set P" (P % of 6.5 m/s); the next tick
# strikes the cue ball along the view and resets the trigger.
# Expected from the float reference (emulator/physics): 40 % power is a cue speed of 2.6 m/s;
# strike(Shot(0, 2.6)) gives 200027.1 um/tick along +x, then one tick of sliding takes off
# mu_s g = 4905 um/tick: 195122.1 (tolerance: the strike's 0.1 %, 200 um/tick, plus 2).
function pool:table/setup
kill @e[tag=pool.ball]
function pool:table/rack/ball {id:0, x:635000, z:635000, item:"minecraft:white_concrete"}
tp @s ~ ~ ~ -90 0
# the trigger is enabled for each player by the controls' tick
trigger pool.power set 40
assert not score @s pool.power matches 40
await delay 1
trigger pool.power set 40
assert score @s pool.power matches 40
await score @s pool.power matches 0
assert score $resting pool.game matches 0
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vx matches 194920..195324
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vz matches -2..2
assert score $shot.speed pool.game matches 2600
