# pool:physics/separate/pair — if ball @s (b) and the ball tagged pool.self (a) are closer than
# 2R + 10 um, move each half the shortfall apart along the line of centres (velocities unchanged;
# the next tick's sweep finds the contact at once if they still approach).
# Reads: #a.x #a.z pool.tmp, @s pool.x pool.z. Writes: both balls' pool.x pool.z pool.x0 pool.z0
# (a rolling ball's line moves with it), #a.x #a.z; temporaries #g #sx #sz pool.tmp.
scoreboard players operation $x pool.math = @s pool.x
scoreboard players operation $x pool.math -= #a.x pool.tmp
execute unless score $x pool.math matches -57159..57159 run return 0
scoreboard players operation $z pool.math = @s pool.z
scoreboard players operation $z pool.math -= #a.z pool.tmp
execute unless score $z pool.math matches -57159..57159 run return 0
# cheap reject in quarter-um units: (dx/4)^2 + (dz/4)^2 >= 14292^2 (= 204261264) means more than
# 2R + 10 = 4 x 14290 apart even with both quotients rounded the wrong way
scoreboard players operation #g pool.tmp = $x pool.math
scoreboard players operation #g pool.tmp /= #4 pool.const
scoreboard players operation #g pool.tmp *= #g pool.tmp
scoreboard players operation #sz pool.tmp = $z pool.math
scoreboard players operation #sz pool.tmp /= #4 pool.const
scoreboard players operation #sz pool.tmp *= #sz pool.tmp
scoreboard players operation #g pool.tmp += #sz pool.tmp
execute if score #g pool.tmp matches 204261264.. run return 0
function pool:math/normalize
# #g = half the shortfall, rounded up: (2R + 10 - len + 1) / 2
scoreboard players operation #g pool.tmp = $2R pool.const
scoreboard players add #g pool.tmp 11
scoreboard players operation #g pool.tmp -= $len pool.math
execute if score #g pool.tmp matches ..1 run return 0
scoreboard players operation #g pool.tmp /= #2 pool.const
scoreboard players operation $a pool.math = #g pool.tmp
scoreboard players operation $b pool.math = $ux pool.math
function pool:math/mul_unit
scoreboard players operation #sx pool.tmp = $out pool.math
scoreboard players operation $b pool.math = $uz pool.math
function pool:math/mul_unit
scoreboard players operation #sz pool.tmp = $out pool.math
function pool:physics/separate/shift
scoreboard players operation #sx pool.tmp *= #-1 pool.const
scoreboard players operation #sz pool.tmp *= #-1 pool.const
execute as @e[tag=pool.self] run function pool:physics/separate/shift
scoreboard players operation #a.x pool.tmp += #sx pool.tmp
scoreboard players operation #a.z pool.tmp += #sz pool.tmp
