# pool:physics/detect/sweep/rails — first rail line (R inside a cushion) that a ball's chord
# crosses.
# Reads: #sweep.a.bx #sweep.a.bz #sweep.a.ex #sweep.a.ez pool.tmp (chord start and end, um).
# Writes: #sweep.rf pool.tmp (fraction 0..10000 of the interval, 10001 when none), #sweep.rail
# pool.tmp (1 left x=R, 2 right x=L-R, 3 near z=R, 4 far z=W-R), #sweep.pocket pool.tmp (1 when the
# crossing lies in a pocket opening); temporaries #sweep.c0 #sweep.c1 #sweep.cf pool.tmp and
# pool:math/div_1e4's.
scoreboard players set #sweep.rf pool.tmp 10001
scoreboard players set #sweep.rail pool.tmp 0
scoreboard players set #sweep.pocket pool.tmp 0
# left
scoreboard players operation #sweep.c0 pool.tmp = #sweep.a.bx pool.tmp
scoreboard players operation #sweep.c0 pool.tmp -= $R pool.const
scoreboard players operation #sweep.c1 pool.tmp = #sweep.a.ex pool.tmp
scoreboard players operation #sweep.c1 pool.tmp -= $R pool.const
function pool:physics/detect/sweep/rail_cross
execute if score #sweep.cf pool.tmp < #sweep.rf pool.tmp run scoreboard players set #sweep.rail pool.tmp 1
scoreboard players operation #sweep.rf pool.tmp < #sweep.cf pool.tmp
# right
scoreboard players operation #sweep.c0 pool.tmp = $L pool.const
scoreboard players operation #sweep.c0 pool.tmp -= $R pool.const
scoreboard players operation #sweep.c1 pool.tmp = #sweep.c0 pool.tmp
scoreboard players operation #sweep.c0 pool.tmp -= #sweep.a.bx pool.tmp
scoreboard players operation #sweep.c1 pool.tmp -= #sweep.a.ex pool.tmp
function pool:physics/detect/sweep/rail_cross
execute if score #sweep.cf pool.tmp < #sweep.rf pool.tmp run scoreboard players set #sweep.rail pool.tmp 2
scoreboard players operation #sweep.rf pool.tmp < #sweep.cf pool.tmp
# near
scoreboard players operation #sweep.c0 pool.tmp = #sweep.a.bz pool.tmp
scoreboard players operation #sweep.c0 pool.tmp -= $R pool.const
scoreboard players operation #sweep.c1 pool.tmp = #sweep.a.ez pool.tmp
scoreboard players operation #sweep.c1 pool.tmp -= $R pool.const
function pool:physics/detect/sweep/rail_cross
execute if score #sweep.cf pool.tmp < #sweep.rf pool.tmp run scoreboard players set #sweep.rail pool.tmp 3
scoreboard players operation #sweep.rf pool.tmp < #sweep.cf pool.tmp
# far
scoreboard players operation #sweep.c0 pool.tmp = $W pool.const
scoreboard players operation #sweep.c0 pool.tmp -= $R pool.const
scoreboard players operation #sweep.c1 pool.tmp = #sweep.c0 pool.tmp
scoreboard players operation #sweep.c0 pool.tmp -= #sweep.a.bz pool.tmp
scoreboard players operation #sweep.c1 pool.tmp -= #sweep.a.ez pool.tmp
function pool:physics/detect/sweep/rail_cross
execute if score #sweep.cf pool.tmp < #sweep.rf pool.tmp run scoreboard players set #sweep.rail pool.tmp 4
scoreboard players operation #sweep.rf pool.tmp < #sweep.cf pool.tmp
execute if score #sweep.rail pool.tmp matches 1.. run function pool:physics/detect/sweep/pocket
