# pool:physics/events/begin — start a physics tick: every ball in play is saved at time 0 and marked dirty
# (needs a trial), except the settled ones (pool.settled: at rest without spin, saved, chord a
# point at the ball, as pool:physics/events/trial left them; whatever moves one removes the tag).
# Writes: #now #finishing #nohit.t #same #work pool.tmp, the balls' saved scores, tag pool.dirty.
scoreboard players set #now pool.tmp 0
scoreboard players set #finishing pool.tmp 0
scoreboard players set #nohit.t pool.tmp -1
scoreboard players set #same pool.tmp 0
execute as @e[tag=pool.ball,tag=!pool.settled,scores={pool.state=0..2}] run function pool:physics/events/save
tag @e[tag=pool.ball,tag=!pool.settled,scores={pool.state=0..2}] add pool.dirty
# 16 balls saved: 14 commands each
scoreboard players add #work pool.tmp 230
