# pool:physics/detect/pair/separating — for a contact the sweep puts at once (at #events.now):
# returns 1 when b (@s) and a (tagged pool.self) do not approach there, s = (v_a - v_b) . n <= 0
# with n = (r_b - r_a)/|r_b - r_a|: the test of pool:physics/resolve/ball_ball/collide, with the
# velocities saved at the chords' starts. Their chords can still converge (a sliding ball's path
# curves away from its chord); such a pair is no event: resolving it would change nothing and find
# it again at the same time for ever.
# Reads: #sweep.dx #sweep.dz pool.tmp (r_b - r_a at #events.now, from the sweep), @s and pool.self's
# pool.bvx pool.bvz.
# Writes: #pair.s pool.tmp; the math library's temporaries.
scoreboard players operation $x pool.math = #sweep.dx pool.tmp
scoreboard players operation $z pool.math = #sweep.dz pool.tmp
function pool:math/normalize
execute as @e[tag=pool.self] run scoreboard players operation $a pool.math = @s pool.bvx
scoreboard players operation $a pool.math -= @s pool.bvx
scoreboard players operation $b pool.math = $ux pool.math
function pool:math/mul_unit
scoreboard players operation #pair.s pool.tmp = $out pool.math
execute as @e[tag=pool.self] run scoreboard players operation $a pool.math = @s pool.bvz
scoreboard players operation $a pool.math -= @s pool.bvz
scoreboard players operation $b pool.math = $uz pool.math
function pool:math/mul_unit
scoreboard players operation #pair.s pool.tmp += $out pool.math
execute if score #pair.s pool.tmp matches ..0 run return 1
return 0
