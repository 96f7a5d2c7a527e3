# pool:physics/events/cost/advance — add to #cost.next the commands pool:physics/motion/advance
# takes to move a ball in state #cost.state with #cost.tau of sliding left by #cost.step (an
# estimate from the profile, on the high side): at rest 10, a whole tick of sliding 90, a part of
# sliding 210, any rolling 180, the end of sliding within the step (the slide, the rolling phase's
# start and the roll) 630.
# Reads: #cost.state #cost.tau #cost.step pool.tmp. Writes: #cost.next pool.tmp.
execute if score #cost.state pool.tmp matches 0 run return run scoreboard players add #cost.next pool.tmp 10
execute if score #cost.state pool.tmp matches 2 run return run scoreboard players add #cost.next pool.tmp 180
execute if score #cost.tau pool.tmp < #cost.step pool.tmp run return run scoreboard players add #cost.next pool.tmp 630
execute if score #cost.step pool.tmp matches 10000 run return run scoreboard players add #cost.next pool.tmp 90
scoreboard players add #cost.next pool.tmp 210
