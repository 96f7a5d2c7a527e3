# @batch unload
# @afterbatch function pool:load
# @timeout 20
# pool:unload removes what the pack made: after a table, a break and a few ticks, no ball entity
# and no objective of pool:load is left, and pool:load sets the pack up again. In a batch of its
# own: unloading takes the objectives from any test running beside it, and the batch's end loads
# the pack again for the batches after it.
function pool:table/setup
function pool:api/shot {angle:0, speed:6500, tip_x:0, tip_y:0, elevation:0}
await delay 3
function pool:unload
assert not entity @e[tag=pool.ball]
# an objective can be added only when it does not exist: these were removed (the ball state, the
# temporaries, the math library, the constants, the game state, the trigger)
scoreboard objectives add unload.test dummy
execute store success score #id unload.test run scoreboard objectives add pool.id dummy
execute store success score #tmp unload.test run scoreboard objectives add pool.tmp dummy
execute store success score #math unload.test run scoreboard objectives add pool.math dummy
execute store success score #const unload.test run scoreboard objectives add pool.const dummy
execute store success score #game unload.test run scoreboard objectives add pool.game dummy
execute store success score #power unload.test run scoreboard objectives add pool.power trigger
assert score #id unload.test matches 1
assert score #tmp unload.test matches 1
assert score #math unload.test matches 1
assert score #const unload.test matches 1
assert score #game unload.test matches 1
assert score #power unload.test matches 1
# loaded again, the pack sets up a table again
function pool:load
function pool:table/setup
execute store result score #balls unload.test if entity @e[tag=pool.ball]
assert score #balls unload.test matches 16
assert score $resting pool.game matches 1
scoreboard objectives remove unload.test
