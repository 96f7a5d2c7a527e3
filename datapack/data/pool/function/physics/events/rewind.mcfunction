# pool:physics/events/rewind — bring @s to the event time #te: back to its saved state (time pool.bt), then
# advance by #te - bt. Reads: #te pool.tmp, @s saved scores. Writes: @s state; #step pool.tmp.
function pool:physics/events/restore
scoreboard players operation #step pool.tmp = #te pool.tmp
scoreboard players operation #step pool.tmp -= @s pool.bt
function pool:physics/motion/advance
