# pool:physics/events/cost/rewind — add to #cost.next the estimated commands of
# pool:physics/events/rewind for @s to #events.te: the restore, and the advance from the saved state
# by #events.te - pool.bt.
# Reads: #events.te pool.tmp, @s pool.bt pool.bstate pool.btau. Writes: #cost.next #cost.state
# #cost.tau #cost.step pool.tmp.
scoreboard players add #cost.next pool.tmp 20
scoreboard players operation #cost.step pool.tmp = #events.te pool.tmp
scoreboard players operation #cost.step pool.tmp -= @s pool.bt
scoreboard players operation #cost.state pool.tmp = @s pool.bstate
scoreboard players operation #cost.tau pool.tmp = @s pool.btau
function pool:physics/events/cost/advance
