# pool:physics/detect/pair/recontact — b (@s) and a (tagged pool.self) touch at once (at
# #events.now) but do not approach there (#pair.s <= 0, or their resolution at this time found
# so); they can still run into each other later in the tick: a ball that a collision stopped next
# to another keeps its spin and slides into it. Their approach along the normal n over the rest of
# the tick (f = 0 .. 1) is taken as c(f) = -P f + K f^2, with P = -s rem / 10000 (the speed at
# which they part now, s <= 0) and K - P = C, the approach of the chords' ends. When c reaches
# $recontact pool.const (50 um) within the tick, at f = (P + sqrt(P^2 + 4 K d)) / (2 K), that is
# their contact: pool:physics/resolve/ball_ball/meet moves it back to where they touch and the
# collision passes the momentum on (pushing them apart at the tick's end, they kept their
# velocities). Otherwise it is no event (pool:physics/detect/pair/touching). The overlap d is
# where a pair that touches without speed is taken: a smaller one would hand the push on by more
# and smaller collisions (at most about one every sqrt(d / (mu_s g)) = 0.1 tick).
# Reads: #pair.s #events.rem #events.now pool.tmp, the chords #sweep.a.bx ... #sweep.b.ez (from
# #events.now), $ux $uz pool.math (n, from pool:physics/detect/pair/separating).
# Writes: #detect.t pool.tmp (returns 1), or tags pool.touch (returns 0); #cost.work #pair.c
# #pair.p #pair.k #pair.d #pair.sc #sweep.f pool.tmp and the math library's temporaries.
scoreboard players add #cost.work pool.tmp 150
# C = -(n . D), D the chords' relative move (b's less a's)
scoreboard players operation $a pool.math = #sweep.b.ex pool.tmp
scoreboard players operation $a pool.math -= #sweep.b.bx pool.tmp
scoreboard players operation $a pool.math -= #sweep.a.ex pool.tmp
scoreboard players operation $a pool.math += #sweep.a.bx pool.tmp
scoreboard players operation $b pool.math = $ux pool.math
function pool:math/mul_unit
scoreboard players operation #pair.c pool.tmp = $out pool.math
scoreboard players operation $a pool.math = #sweep.b.ez pool.tmp
scoreboard players operation $a pool.math -= #sweep.b.bz pool.tmp
scoreboard players operation $a pool.math -= #sweep.a.ez pool.tmp
scoreboard players operation $a pool.math += #sweep.a.bz pool.tmp
scoreboard players operation $b pool.math = $uz pool.math
function pool:math/mul_unit
scoreboard players operation #pair.c pool.tmp += $out pool.math
scoreboard players operation #pair.c pool.tmp *= #-1 pool.const
execute if score #pair.c pool.tmp < $recontact pool.const run return run function pool:physics/detect/pair/touching
# P >= 0, K = C + P >= d > 0, so that the root lies within the tick
scoreboard players operation $a pool.math = #pair.s pool.tmp
execute if score $a pool.math matches 1.. run scoreboard players set $a pool.math 0
scoreboard players operation $b pool.math = #events.rem pool.tmp
function pool:math/mul_unit
scoreboard players operation #pair.p pool.tmp = $out pool.math
scoreboard players operation #pair.p pool.tmp *= #-1 pool.const
scoreboard players operation #pair.k pool.tmp = #pair.c pool.tmp
scoreboard players operation #pair.k pool.tmp += #pair.p pool.tmp
# all three scaled by sc = K / 16384 + 1 (P < K): P^2 + 4 K d < 2^31 for d < 16384
scoreboard players operation #pair.sc pool.tmp = #pair.k pool.tmp
scoreboard players operation #pair.sc pool.tmp /= #16384 pool.const
scoreboard players add #pair.sc pool.tmp 1
scoreboard players operation #pair.p pool.tmp /= #pair.sc pool.tmp
scoreboard players operation #pair.k pool.tmp /= #pair.sc pool.tmp
scoreboard players operation #pair.d pool.tmp = $recontact pool.const
scoreboard players operation #pair.d pool.tmp /= #pair.sc pool.tmp
scoreboard players operation $in pool.math = #pair.k pool.tmp
scoreboard players operation $in pool.math *= #pair.d pool.tmp
scoreboard players operation $in pool.math *= #4 pool.const
scoreboard players operation #pair.d pool.tmp = #pair.p pool.tmp
scoreboard players operation #pair.d pool.tmp *= #pair.p pool.tmp
scoreboard players operation $in pool.math += #pair.d pool.tmp
function pool:math/isqrt
scoreboard players operation $a pool.math = $out pool.math
scoreboard players operation $a pool.math += #pair.p pool.tmp
scoreboard players operation $b pool.math = #pair.k pool.tmp
scoreboard players operation $b pool.math *= #2 pool.const
function pool:math/div_1e4
scoreboard players operation #sweep.f pool.tmp = $out pool.math
execute unless score #sweep.f pool.tmp matches 1..10000 run return run function pool:physics/detect/pair/touching
function pool:physics/detect/absolute
execute if score #detect.t pool.tmp <= #events.now pool.tmp run return run function pool:physics/detect/pair/touching
return 1
