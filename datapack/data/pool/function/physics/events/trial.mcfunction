# pool:physics/events/trial — the trial of the dirty ball @s (pool:physics/detect/chord/new: a new
# chord to the tick's end) when its estimated cost still fits in this game tick's $budget; otherwise
# @s stays dirty and the physics tick carries over (pool:physics/events/substep).
# Reads: #events.rem #cost.work pool.tmp, @s pool.state pool.tau. Writes: #cost.work #cost.next
# #cost.state #cost.tau #cost.step pool.tmp; through pool:physics/detect/chord/new; tag
# pool.settled.
scoreboard players set #cost.next pool.tmp 40
scoreboard players operation #cost.step pool.tmp = #events.rem pool.tmp
scoreboard players operation #cost.state pool.tmp = @s pool.state
scoreboard players operation #cost.tau pool.tmp = @s pool.tau
function pool:physics/events/cost/advance
scoreboard players operation #cost.next pool.tmp += #cost.work pool.tmp
execute if score #cost.next pool.tmp > $budget pool.const run return 0
scoreboard players operation #cost.work pool.tmp = #cost.next pool.tmp
# a ball at rest without spin (before the trial: one that stops within it has no point chord) keeps
# its point chord, box and saved state until something moves it: pool:physics/events/begin skips it,
# a trial would change nothing
execute if score @s pool.state matches 0 if score @s pool.wy matches 0 run tag @s add pool.settled
function pool:physics/detect/chord/new
