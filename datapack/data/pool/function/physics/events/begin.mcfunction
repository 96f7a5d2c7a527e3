# pool:physics/events/begin — start a physics tick: every ball in play is saved at time 0 and marked
# dirty (needs a trial), except the settled ones (pool.settled: at rest without spin, saved, chord a
# point at the ball, as pool:physics/events/trial left them; whatever moves one removes the tag).
# Writes: #events.now #events.finishing #ball_ball.nohit.t #events.same #cost.work pool.tmp, the
# balls' saved scores, tag pool.dirty.
scoreboard players set #events.now pool.tmp 0
scoreboard players set #events.finishing pool.tmp 0
scoreboard players set #ball_ball.nohit.t pool.tmp -1
scoreboard players set #events.same pool.tmp 0
execute as @e[tag=pool.ball,tag=!pool.settled,scores={pool.state=0..2}] run function pool:physics/events/save
tag @e[tag=pool.ball,tag=!pool.settled,scores={pool.state=0..2}] add pool.dirty
# 16 balls saved: 15 commands each, 23 sliding
scoreboard players add #cost.work pool.tmp 380
