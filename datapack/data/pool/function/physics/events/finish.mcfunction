# pool:physics/events/finish — the end of a complete physics tick: balls that touched another are
# pushed apart, then the balls those pushes moved are looked at again (four passes at most); then
# the displays follow the balls that moved and the table may come to rest. Each ball's separation
# runs only when its estimated cost fits in this game tick's $budget (#cost.work), else the rest
# carries over to the next game tick (#events.finishing pool.tmp: the physics tick is done, only
# this remains).
# Reads/writes: #cost.work #events.finishing #separate.passes pool.tmp, $carry pool.game, tags
# pool.touch pool.shifted pool.again pool.found pool.fresh; through pool:physics/resolve/separate/*,
# pool:physics/display/place and pool:physics/events/at_rest.
execute unless score #events.finishing pool.tmp matches 1 run function pool:physics/events/finish/start
# a pair left touching but not approaching (pool:physics/detect/pair/touching) can end closer than
# 2R along converging chords, and the contact shift of pool:physics/resolve/ball_ball/touch can
# carry a ball a few um into a third one
execute as @e[tag=pool.touch] run function pool:physics/resolve/separate/next_touch
execute if entity @e[tag=pool.touch] run return run scoreboard players set $carry pool.game 1
# a push can carry a ball into a third one
function pool:physics/resolve/separate/passes
execute if score $carry pool.game matches 1 run return 0
tag @e[tag=pool.shifted] remove pool.shifted
scoreboard players set #events.finishing pool.tmp 0
execute as @e[tag=pool.moving] run function pool:physics/display/place
execute unless entity @e[tag=pool.ball,scores={pool.state=1..2}] run function pool:physics/events/at_rest
