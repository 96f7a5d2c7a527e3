# pool:physics/detect/sweep/rails — first rail line (R inside a cushion) that a ball's chord crosses.
# Reads: #a.bx #a.bz #a.ex #a.ez pool.tmp (chord start and end, um).
# Writes: #rf pool.tmp (fraction 0..10000 of the interval, 10001 when none), #rail pool.tmp
# (1 left x=R, 2 right x=L-R, 3 near z=R, 4 far z=W-R), #pocket pool.tmp (1 when the crossing
# lies in a pocket opening); temporaries #c0 #c1 #cf pool.tmp and pool:math/div_1e4's.
scoreboard players set #rf pool.tmp 10001
scoreboard players set #rail pool.tmp 0
scoreboard players set #pocket pool.tmp 0
# left
scoreboard players operation #c0 pool.tmp = #a.bx pool.tmp
scoreboard players operation #c0 pool.tmp -= $R pool.const
scoreboard players operation #c1 pool.tmp = #a.ex pool.tmp
scoreboard players operation #c1 pool.tmp -= $R pool.const
function pool:physics/detect/sweep/rail_cross
execute if score #cf pool.tmp < #rf pool.tmp run scoreboard players set #rail pool.tmp 1
scoreboard players operation #rf pool.tmp < #cf pool.tmp
# right
scoreboard players operation #c0 pool.tmp = $L pool.const
scoreboard players operation #c0 pool.tmp -= $R pool.const
scoreboard players operation #c1 pool.tmp = #c0 pool.tmp
scoreboard players operation #c0 pool.tmp -= #a.bx pool.tmp
scoreboard players operation #c1 pool.tmp -= #a.ex pool.tmp
function pool:physics/detect/sweep/rail_cross
execute if score #cf pool.tmp < #rf pool.tmp run scoreboard players set #rail pool.tmp 2
scoreboard players operation #rf pool.tmp < #cf pool.tmp
# near
scoreboard players operation #c0 pool.tmp = #a.bz pool.tmp
scoreboard players operation #c0 pool.tmp -= $R pool.const
scoreboard players operation #c1 pool.tmp = #a.ez pool.tmp
scoreboard players operation #c1 pool.tmp -= $R pool.const
function pool:physics/detect/sweep/rail_cross
execute if score #cf pool.tmp < #rf pool.tmp run scoreboard players set #rail pool.tmp 3
scoreboard players operation #rf pool.tmp < #cf pool.tmp
# far
scoreboard players operation #c0 pool.tmp = $W pool.const
scoreboard players operation #c0 pool.tmp -= $R pool.const
scoreboard players operation #c1 pool.tmp = #c0 pool.tmp
scoreboard players operation #c0 pool.tmp -= #a.bz pool.tmp
scoreboard players operation #c1 pool.tmp -= #a.ez pool.tmp
function pool:physics/detect/sweep/rail_cross
execute if score #cf pool.tmp < #rf pool.tmp run scoreboard players set #rail pool.tmp 4
scoreboard players operation #rf pool.tmp < #cf pool.tmp
execute if score #rail pool.tmp matches 1.. run function pool:physics/detect/sweep/pocket
