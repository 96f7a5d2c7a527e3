# pool:physics/detect/sweep/pair — first contact of two balls moving along straight chords within the
# rest of the tick: the smallest fraction f (1/10000 of the interval) with |d0 + f D| = 2R while
# approaching, where d0 = b0 - a0 and D = (b1 - b0) - (a1 - a0).
# Reads: #a.bx #a.bz #a.ex #a.ez #b.bx #b.bz #b.ex #b.ez pool.tmp (chord start, end, um).
# Writes: #f pool.tmp (0..10000, or 10001 when they do not touch); temporaries #dx #dz #p #q #h,
# pool:physics/detect/sweep/unit's memo.
# With u = D/|D|: p = -d0.u is the distance to closest approach, q = d0 x u the miss distance;
# contact comes at p - sqrt(D^2 - q^2) for D = $contact = 2R + 20 um: early enough that the
# rounded unit vector (1e-4) never lets balls overlap; the resolver then closes the gap.
# The fraction's step is 1/10000 of the chords: at most 0.1 mm at 10 m/s head-on.
scoreboard players set #f pool.tmp 10001
scoreboard players operation #dx pool.tmp = #b.bx pool.tmp
scoreboard players operation #dx pool.tmp -= #a.bx pool.tmp
scoreboard players operation #dz pool.tmp = #b.bz pool.tmp
scoreboard players operation #dz pool.tmp -= #a.bz pool.tmp
scoreboard players operation $x pool.math = #b.ex pool.tmp
scoreboard players operation $x pool.math -= #b.bx pool.tmp
scoreboard players operation $x pool.math -= #a.ex pool.tmp
scoreboard players operation $x pool.math += #a.bx pool.tmp
scoreboard players operation $z pool.math = #b.ez pool.tmp
scoreboard players operation $z pool.math -= #b.bz pool.tmp
scoreboard players operation $z pool.math -= #a.ez pool.tmp
scoreboard players operation $z pool.math += #a.bz pool.tmp
# cheap reject: separating
function pool:physics/detect/sweep/pair_reject
execute if score #apart pool.tmp matches 1 run return 0
function pool:physics/detect/sweep/unit
execute if score $len pool.math matches 0 run return 0
# p = -(d0 . u)
scoreboard players operation $a pool.math = #dx pool.tmp
scoreboard players operation $b pool.math = $ux pool.math
function pool:math/mul_unit
scoreboard players operation #p pool.tmp = $out pool.math
scoreboard players operation $a pool.math = #dz pool.tmp
scoreboard players operation $b pool.math = $uz pool.math
function pool:math/mul_unit
scoreboard players operation #p pool.tmp += $out pool.math
scoreboard players operation #p pool.tmp *= #-1 pool.const
execute if score #p pool.tmp matches ..0 run return 0
# |q| = |d0x uz - d0z ux|
scoreboard players operation $a pool.math = #dx pool.tmp
scoreboard players operation $b pool.math = $uz pool.math
function pool:math/mul_unit
scoreboard players operation #q pool.tmp = $out pool.math
scoreboard players operation $a pool.math = #dz pool.tmp
scoreboard players operation $b pool.math = $ux pool.math
function pool:math/mul_unit
scoreboard players operation #q pool.tmp -= $out pool.math
execute if score #q pool.tmp matches ..-1 run scoreboard players operation #q pool.tmp *= #-1 pool.const
execute if score #q pool.tmp >= $contact pool.const run return 0
# h = sqrt((D - q)(D + q)) = 2 sqrt((D - q)((D + q)/4))
scoreboard players operation #h pool.tmp = $contact pool.const
scoreboard players operation #h pool.tmp += #q pool.tmp
scoreboard players set #c pool.tmp 4
scoreboard players operation #h pool.tmp /= #c pool.tmp
scoreboard players operation $in pool.math = $contact pool.const
scoreboard players operation $in pool.math -= #q pool.tmp
scoreboard players operation $in pool.math *= #h pool.tmp
function pool:math/isqrt
scoreboard players operation #p pool.tmp -= $out pool.math
scoreboard players operation #p pool.tmp -= $out pool.math
execute if score #p pool.tmp > $len pool.math run return 0
execute if score #p pool.tmp matches ..-1 run scoreboard players set #p pool.tmp 0
scoreboard players operation $a pool.math = #p pool.tmp
scoreboard players operation $b pool.math = $len pool.math
function pool:math/div_1e4
scoreboard players operation #f pool.tmp = $out pool.math
# one unit early: the rounded fraction must not carry the balls into each other
execute if score #f pool.tmp matches 1.. run scoreboard players remove #f pool.tmp 1
