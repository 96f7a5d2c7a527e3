# pool:physics/step — one game tick of table physics. Events found by swept tests are resolved in
# time order within the physics tick (pool:physics/events/substep). A game tick does only the work
# whose estimated cost fits in $budget (#cost.work counts it): past that the rest of the physics
# tick carries over ($carry pool.game = 1) to the next game tick, which goes on from where this one
# stopped, so the table runs in slow motion through a burst of events (the break) and no game tick
# exceeds the command budget. When a physics tick is complete, pool:physics/events/finish ends it.
# Reads/writes: every ball's scores; #events.now #events.count #cost.work #events.finishing
# pool.tmp; $carry $resting pool.game.
scoreboard players set #events.count pool.tmp 0
scoreboard players set #cost.work pool.tmp 0
execute unless score $carry pool.game matches 1 run function pool:physics/events/begin
scoreboard players set $carry pool.game 0
execute unless score #events.finishing pool.tmp matches 1 run function pool:physics/events/substep
execute if score $carry pool.game matches 1 run return 0
function pool:physics/events/finish
