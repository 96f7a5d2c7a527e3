# pool:physics/resolve — resolve the event found by the sweep, as its first ball @s.
# Reads: #events.kind #events.rail pool.tmp. Writes: the balls' scores through the resolvers.
execute if score #events.kind pool.tmp matches 1 run function pool:physics/resolve/ball_ball
execute if score #events.kind pool.tmp matches 2 run function pool:physics/resolve/cushion
execute if score #events.kind pool.tmp matches 3 run function pool:physics/resolve/pocket
