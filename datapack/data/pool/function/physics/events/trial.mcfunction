# pool:physics/events/trial — the trial of the dirty ball @s (pool:physics/detect/chord/new: a new chord to the tick's
# end) when its estimated cost still fits in this game tick's $budget; otherwise @s stays dirty
# and the physics tick carries over (pool:physics/events/substep).
# Reads: #rem #work pool.tmp, @s pool.state pool.tau. Writes: #work #c #cs #ctau #step pool.tmp;
# through pool:physics/detect/chord/new; tag pool.settled.
scoreboard players set #c pool.tmp 40
scoreboard players operation #step pool.tmp = #rem pool.tmp
scoreboard players operation #cs pool.tmp = @s pool.state
scoreboard players operation #ctau pool.tmp = @s pool.tau
function pool:physics/events/cost/advance
scoreboard players operation #c pool.tmp += #work pool.tmp
execute if score #c pool.tmp > $budget pool.const run return 0
scoreboard players operation #work pool.tmp = #c pool.tmp
# a ball at rest without spin (before the trial: one that stops within it has no point chord)
# keeps its point chord, box and saved state until something moves it: pool:physics/events/begin skips
# it, a trial would change nothing
execute if score @s pool.state matches 0 if score @s pool.wy matches 0 run tag @s add pool.settled
function pool:physics/detect/chord/new
