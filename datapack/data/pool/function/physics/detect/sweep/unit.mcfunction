# pool:physics/detect/sweep/unit — pool:math/normalize of (x, z), remembering the last input and
# result: normalize is a pure function of $x $z, and one ball's search tests every ball at rest
# against the same relative motion (the ball's own chord), so most calls repeat the last one.
# Reads: $x $z pool.math. Writes: $ux $uz $len pool.math (as pool:math/normalize); the memo
# #sweep.unit.x #sweep.unit.z #sweep.unit.ux #sweep.unit.uz #sweep.unit.len pool.tmp; #cost.work
# pool.tmp (+130, normalize's cost).
execute if score $x pool.math = #sweep.unit.x pool.tmp if score $z pool.math = #sweep.unit.z pool.tmp run return run function pool:physics/detect/sweep/unit_memo
function pool:math/normalize
scoreboard players add #cost.work pool.tmp 130
scoreboard players operation #sweep.unit.x pool.tmp = $x pool.math
scoreboard players operation #sweep.unit.z pool.tmp = $z pool.math
scoreboard players operation #sweep.unit.ux pool.tmp = $ux pool.math
scoreboard players operation #sweep.unit.uz pool.tmp = $uz pool.math
scoreboard players operation #sweep.unit.len pool.tmp = $len pool.math
