# pool:physics/step — one tick of table physics: events found by swept tests are resolved in time
# order within the tick (at most $max_events), then the displays of the balls that moved follow.
# Every ball in play is saved at the tick's start (time 0) and marked dirty (needs a trial).
# Reads/writes: every ball's scores; #now #events #nohit.t pool.tmp; $resting pool.game.
scoreboard players set #now pool.tmp 0
scoreboard players set #events pool.tmp 0
scoreboard players set #nohit.t pool.tmp -1
execute as @e[tag=pool.ball,scores={pool.state=0..2}] run function pool:ball/save
tag @e[tag=pool.ball,scores={pool.state=0..2}] add pool.dirty
function pool:physics/substep
# balls that touched another this tick: a pair left touching but not approaching
# (pool:physics/find/touching) can end closer than 2R along converging chords, and the contact
# shift of pool:physics/resolve/touch can carry a ball a few um into a third one
execute as @e[tag=pool.touch,scores={pool.state=0..2}] run function pool:physics/separate/ball
tag @e[tag=pool.touch] remove pool.touch
execute as @e[tag=pool.moving] run function pool:ball/display/place
execute unless entity @e[tag=pool.ball,scores={pool.state=1..2}] run function pool:physics/at_rest
