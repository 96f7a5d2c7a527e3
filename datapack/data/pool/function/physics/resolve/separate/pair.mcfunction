# pool:physics/resolve/separate/pair — if ball @s (b) and the ball tagged pool.self (a) are closer than
# 2R + 10 um (with #sep_act 1; closer than 2R with #sep_act 11), move each half the shortfall to
# 2R + 10 um apart along the line of centres (velocities unchanged; the next tick's sweep finds
# the contact at once if they still approach).
# Reads: #a.x #a.z #sep_far #sep_act pool.tmp (set by the callers), @s pool.x pool.z.
# Writes: both balls' pool.x pool.z pool.x0 pool.z0 (a rolling ball's line moves with it),
# #a.x #a.z; temporaries #g #sx #sz pool.tmp.
scoreboard players operation $x pool.math = @s pool.x
scoreboard players operation $x pool.math -= #a.x pool.tmp
execute unless score $x pool.math matches -57159..57159 run return 0
scoreboard players operation $z pool.math = @s pool.z
scoreboard players operation $z pool.math -= #a.z pool.tmp
execute unless score $z pool.math matches -57159..57159 run return 0
# cheap reject in quarter-um units: (dx/4)^2 + (dz/4)^2 >= #sep_far means far enough apart even
# with both quotients rounded the wrong way (14292^2 = 204261264 for 2R + 10 = 4 x 14290,
# 14290^2 = 204204100 for 2R = 4 x 14287.5)
scoreboard players operation #g pool.tmp = $x pool.math
scoreboard players operation #g pool.tmp /= #4 pool.const
scoreboard players operation #g pool.tmp *= #g pool.tmp
scoreboard players operation #sz pool.tmp = $z pool.math
scoreboard players operation #sz pool.tmp /= #4 pool.const
scoreboard players operation #sz pool.tmp *= #sz pool.tmp
scoreboard players operation #g pool.tmp += #sz pool.tmp
execute if score #g pool.tmp >= #sep_far pool.tmp run return 0
function pool:math/normalize
# #g = half the shortfall, rounded up: (2R + 10 - len + 1) / 2, when 2R + 11 - len > #sep_act
scoreboard players operation #g pool.tmp = $2R pool.const
scoreboard players add #g pool.tmp 11
scoreboard players operation #g pool.tmp -= $len pool.math
execute if score #g pool.tmp <= #sep_act pool.tmp run return 0
scoreboard players operation #g pool.tmp /= #2 pool.const
scoreboard players operation $a pool.math = #g pool.tmp
scoreboard players operation $b pool.math = $ux pool.math
function pool:math/mul_unit
scoreboard players operation #sx pool.tmp = $out pool.math
scoreboard players operation $b pool.math = $uz pool.math
function pool:math/mul_unit
scoreboard players operation #sz pool.tmp = $out pool.math
function pool:physics/resolve/separate/shift
scoreboard players operation #sx pool.tmp *= #-1 pool.const
scoreboard players operation #sz pool.tmp *= #-1 pool.const
execute as @e[tag=pool.self] run function pool:physics/resolve/separate/shift
scoreboard players operation #a.x pool.tmp += #sx pool.tmp
scoreboard players operation #a.z pool.tmp += #sz pool.tmp
