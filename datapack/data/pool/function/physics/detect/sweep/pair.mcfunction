# pool:physics/detect/sweep/pair — first contact of two balls moving along straight chords within
# the rest of the tick: the smallest fraction f (1/10000 of the interval) with |d0 + f D| = 2R while
# approaching, where d0 = b0 - a0 and D = (b1 - b0) - (a1 - a0).
# Reads: #sweep.a.bx #sweep.a.bz #sweep.a.ex #sweep.a.ez #sweep.b.bx #sweep.b.bz #sweep.b.ex
# #sweep.b.ez pool.tmp (chord start, end, um).
# Writes: #sweep.f pool.tmp (0..10000, or 10001 when they do not touch); temporaries #sweep.dx
# #sweep.dz #sweep.p #sweep.q #sweep.h, pool:physics/detect/sweep/unit's memo.
# With u = D/|D|: p = -d0.u is the distance to closest approach, q = d0 x u the miss distance;
# contact comes at p - sqrt(D^2 - q^2) for D = $contact = 2R + 20 um: early enough that the
# rounded unit vector (1e-4) never lets balls overlap; the resolver then closes the gap.
# The fraction's step is 1/10000 of the chords: at most 0.1 mm at 10 m/s head-on.
scoreboard players set #sweep.f pool.tmp 10001
scoreboard players operation #sweep.dx pool.tmp = #sweep.b.bx pool.tmp
scoreboard players operation #sweep.dx pool.tmp -= #sweep.a.bx pool.tmp
scoreboard players operation #sweep.dz pool.tmp = #sweep.b.bz pool.tmp
scoreboard players operation #sweep.dz pool.tmp -= #sweep.a.bz pool.tmp
scoreboard players operation $x pool.math = #sweep.b.ex pool.tmp
scoreboard players operation $x pool.math -= #sweep.b.bx pool.tmp
scoreboard players operation $x pool.math -= #sweep.a.ex pool.tmp
scoreboard players operation $x pool.math += #sweep.a.bx pool.tmp
scoreboard players operation $z pool.math = #sweep.b.ez pool.tmp
scoreboard players operation $z pool.math -= #sweep.b.bz pool.tmp
scoreboard players operation $z pool.math -= #sweep.a.ez pool.tmp
scoreboard players operation $z pool.math += #sweep.a.bz pool.tmp
# cheap reject: separating
function pool:physics/detect/sweep/pair_reject
execute if score #sweep.apart pool.tmp matches 1 run return 0
function pool:physics/detect/sweep/unit
execute if score $len pool.math matches 0 run return 0
# p = -(d0 . u)
scoreboard players operation $a pool.math = #sweep.dx pool.tmp
scoreboard players operation $b pool.math = $ux pool.math
function pool:math/mul_unit
scoreboard players operation #sweep.p pool.tmp = $out pool.math
scoreboard players operation $a pool.math = #sweep.dz pool.tmp
scoreboard players operation $b pool.math = $uz pool.math
function pool:math/mul_unit
scoreboard players operation #sweep.p pool.tmp += $out pool.math
scoreboard players operation #sweep.p pool.tmp *= #-1 pool.const
execute if score #sweep.p pool.tmp matches ..0 run return 0
# |q| = |d0x uz - d0z ux|
scoreboard players operation $a pool.math = #sweep.dx pool.tmp
scoreboard players operation $b pool.math = $uz pool.math
function pool:math/mul_unit
scoreboard players operation #sweep.q pool.tmp = $out pool.math
scoreboard players operation $a pool.math = #sweep.dz pool.tmp
scoreboard players operation $b pool.math = $ux pool.math
function pool:math/mul_unit
scoreboard players operation #sweep.q pool.tmp -= $out pool.math
execute if score #sweep.q pool.tmp matches ..-1 run scoreboard players operation #sweep.q pool.tmp *= #-1 pool.const
execute if score #sweep.q pool.tmp >= $contact pool.const run return 0
# h = sqrt((D - q)(D + q)) = 2 sqrt((D - q)((D + q)/4))
scoreboard players operation #sweep.h pool.tmp = $contact pool.const
scoreboard players operation #sweep.h pool.tmp += #sweep.q pool.tmp
scoreboard players set #sweep.four pool.tmp 4
scoreboard players operation #sweep.h pool.tmp /= #sweep.four pool.tmp
scoreboard players operation $in pool.math = $contact pool.const
scoreboard players operation $in pool.math -= #sweep.q pool.tmp
scoreboard players operation $in pool.math *= #sweep.h pool.tmp
function pool:math/isqrt
scoreboard players operation #sweep.p pool.tmp -= $out pool.math
scoreboard players operation #sweep.p pool.tmp -= $out pool.math
execute if score #sweep.p pool.tmp > $len pool.math run return 0
execute if score #sweep.p pool.tmp matches ..-1 run scoreboard players set #sweep.p pool.tmp 0
scoreboard players operation $a pool.math = #sweep.p pool.tmp
scoreboard players operation $b pool.math = $len pool.math
function pool:math/div_1e4
scoreboard players operation #sweep.f pool.tmp = $out pool.math
# one unit early: the rounded fraction must not carry the balls into each other
execute if score #sweep.f pool.tmp matches 1.. run scoreboard players remove #sweep.f pool.tmp 1
