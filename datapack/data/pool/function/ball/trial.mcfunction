# pool:ball/trial — start of a sub-step for @s: mark it moving or not, save its state (the chord
# start), advance it by #step to the sub-step's end (the chord end) and box the chord.
# Reads: #step pool.tmp, @s scores. Writes: tag pool.moving, @s saved and current scores, box.
tag @s remove pool.moving
execute if score @s pool.state matches 1..2 run tag @s add pool.moving
function pool:ball/save
function pool:ball/advance
function pool:ball/chord_box
