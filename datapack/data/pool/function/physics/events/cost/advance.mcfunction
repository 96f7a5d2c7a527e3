# pool:physics/events/cost/advance — add to #c the commands pool:physics/motion/advance takes to move a ball in
# state #cs with #ctau of sliding left by #step (an estimate from the profile, on the high side):
# at rest 10, a whole tick of sliding 60, a part of sliding or any rolling 180, the end of sliding
# within the step (the slide, the rolling phase's start and the roll) 600.
# Reads: #cs #ctau #step pool.tmp. Writes: #c pool.tmp.
execute if score #cs pool.tmp matches 0 run return run scoreboard players add #c pool.tmp 10
execute if score #cs pool.tmp matches 2 run return run scoreboard players add #c pool.tmp 180
execute if score #ctau pool.tmp < #step pool.tmp run return run scoreboard players add #c pool.tmp 600
execute if score #step pool.tmp matches 10000 run return run scoreboard players add #c pool.tmp 60
scoreboard players add #c pool.tmp 180
