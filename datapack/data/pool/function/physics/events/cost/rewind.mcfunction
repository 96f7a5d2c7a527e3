# pool:physics/events/cost/rewind — add to #c the estimated commands of pool:physics/events/rewind for @s to #te:
# the restore, and the advance from the saved state by #te - pool.bt.
# Reads: #te pool.tmp, @s pool.bt pool.bstate pool.btau. Writes: #c #cs #ctau #step pool.tmp.
scoreboard players add #c pool.tmp 20
scoreboard players operation #step pool.tmp = #te pool.tmp
scoreboard players operation #step pool.tmp -= @s pool.bt
scoreboard players operation #cs pool.tmp = @s pool.bstate
scoreboard players operation #ctau pool.tmp = @s pool.btau
function pool:physics/events/cost/advance
