# pool:physics/events/rewind — bring @s to the event time #events.te: back to its saved state (time
# pool.bt), then advance by #events.te - bt. Reads: #events.te pool.tmp, @s saved scores. Writes: @s
# state; #motion.step pool.tmp.
function pool:physics/events/restore
scoreboard players operation #motion.step pool.tmp = #events.te pool.tmp
scoreboard players operation #motion.step pool.tmp -= @s pool.bt
function pool:physics/motion/advance
