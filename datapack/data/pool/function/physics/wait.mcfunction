# pool:physics/wait — the event cap is reached: bring the balls still at the tick's end back to
# the last event's time #now, so that none goes on past an event not resolved. A sliding ball's
# true (curved) path can be inside another ball where its chord was not; the rest of the tick
# would have resolved that contact, so such pairs are pushed apart here instead.
# Reads: #now pool.tmp. Writes: those balls' states; #te pool.tmp.
scoreboard players operation #te pool.tmp = #now pool.tmp
execute as @e[tag=pool.ball,tag=!pool.dirty,scores={pool.state=0..2}] run function pool:ball/rewind
execute as @e[tag=pool.ball,scores={pool.state=1..2}] run function pool:physics/separate/ball
