# pool:physics/resolve/separate/pair — if ball @s (b) and the ball tagged pool.self (a) are closer
# than 2R + 10 um (with #separate.act 1; closer than 2R with #separate.act 11), move each half the
# shortfall to 2R + 10 um apart along the line of centres (velocities unchanged; the next tick's
# sweep finds the contact at once if they still approach).
# Reads: #separate.a.x #separate.a.z #separate.far #separate.act pool.tmp (set by the callers), @s
# pool.x pool.z.
# Writes: both balls' pool.x pool.z pool.x0 pool.z0 (a rolling ball's line moves with it),
# #separate.a.x #separate.a.z; temporaries #separate.g #separate.sx #separate.sz pool.tmp.
scoreboard players operation $x pool.math = @s pool.x
scoreboard players operation $x pool.math -= #separate.a.x pool.tmp
execute unless score $x pool.math matches -57159..57159 run return 0
scoreboard players operation $z pool.math = @s pool.z
scoreboard players operation $z pool.math -= #separate.a.z pool.tmp
execute unless score $z pool.math matches -57159..57159 run return 0
# cheap reject in quarter-um units: (dx/4)^2 + (dz/4)^2 >= #separate.far means far enough apart even
# with both quotients rounded the wrong way (14292^2 = 204261264 for 2R + 10 = 4 x 14290,
# 14290^2 = 204204100 for 2R = 4 x 14287.5)
scoreboard players operation #separate.g pool.tmp = $x pool.math
scoreboard players operation #separate.g pool.tmp /= #4 pool.const
scoreboard players operation #separate.g pool.tmp *= #separate.g pool.tmp
scoreboard players operation #separate.sz pool.tmp = $z pool.math
scoreboard players operation #separate.sz pool.tmp /= #4 pool.const
scoreboard players operation #separate.sz pool.tmp *= #separate.sz pool.tmp
scoreboard players operation #separate.g pool.tmp += #separate.sz pool.tmp
execute if score #separate.g pool.tmp >= #separate.far pool.tmp run return 0
# the distance exactly (pool:math/gap: len = 2R + 1 + gap; pool:math/normalize's length can be 2 um
# off, which left pairs overlapping)
function pool:math/gap
execute if score $out pool.math matches 2001 run return 0
# #separate.g = half the shortfall, rounded up: (2R + 10 - len + 1) / 2, when 2R + 11 - len >
# #separate.act
scoreboard players set #separate.g pool.tmp 10
scoreboard players operation #separate.g pool.tmp -= $out pool.math
execute if score #separate.g pool.tmp <= #separate.act pool.tmp run return 0
scoreboard players operation #separate.g pool.tmp /= #2 pool.const
scoreboard players operation $a pool.math = #separate.g pool.tmp
scoreboard players operation $b pool.math = $ux pool.math
function pool:math/mul_unit
scoreboard players operation #separate.sx pool.tmp = $out pool.math
scoreboard players operation $b pool.math = $uz pool.math
function pool:math/mul_unit
scoreboard players operation #separate.sz pool.tmp = $out pool.math
function pool:physics/resolve/separate/shift
scoreboard players operation #separate.sx pool.tmp *= #-1 pool.const
scoreboard players operation #separate.sz pool.tmp *= #-1 pool.const
execute as @e[tag=pool.self] run function pool:physics/resolve/separate/shift
scoreboard players operation #separate.a.x pool.tmp += #separate.sx pool.tmp
scoreboard players operation #separate.a.z pool.tmp += #separate.sz pool.tmp
