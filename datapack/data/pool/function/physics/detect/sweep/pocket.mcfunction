# pool:physics/detect/sweep/pocket — whether the crossing of rail #sweep.rail at fraction #sweep.rf
# of the chord lies in a pocket opening: within $corner_open of a corner, or $side_open of a long
# rail's middle.
# Reads: #sweep.rail #sweep.rf #sweep.a.bx #sweep.a.bz #sweep.a.ex #sweep.a.ez pool.tmp. Writes:
# #sweep.pocket pool.tmp; temporaries #sweep.along #sweep.m.
scoreboard players operation $b pool.math = #sweep.rf pool.tmp
execute if score #sweep.rail pool.tmp matches 1..2 run scoreboard players operation $a pool.math = #sweep.a.ez pool.tmp
execute if score #sweep.rail pool.tmp matches 1..2 run scoreboard players operation $a pool.math -= #sweep.a.bz pool.tmp
execute if score #sweep.rail pool.tmp matches 3..4 run scoreboard players operation $a pool.math = #sweep.a.ex pool.tmp
execute if score #sweep.rail pool.tmp matches 3..4 run scoreboard players operation $a pool.math -= #sweep.a.bx pool.tmp
function pool:math/mul_unit
scoreboard players operation #sweep.along pool.tmp = $out pool.math
execute if score #sweep.rail pool.tmp matches 1..2 run scoreboard players operation #sweep.along pool.tmp += #sweep.a.bz pool.tmp
execute if score #sweep.rail pool.tmp matches 3..4 run scoreboard players operation #sweep.along pool.tmp += #sweep.a.bx pool.tmp
# #sweep.m = the rail's length: W for the short rails, L for the long ones
execute if score #sweep.rail pool.tmp matches 1..2 run scoreboard players operation #sweep.m pool.tmp = $W pool.const
execute if score #sweep.rail pool.tmp matches 3..4 run scoreboard players operation #sweep.m pool.tmp = $L pool.const
execute if score #sweep.along pool.tmp <= $corner_open pool.const run scoreboard players set #sweep.pocket pool.tmp 1
scoreboard players operation #sweep.m pool.tmp -= #sweep.along pool.tmp
execute if score #sweep.m pool.tmp <= $corner_open pool.const run scoreboard players set #sweep.pocket pool.tmp 1
execute if score #sweep.rail pool.tmp matches 1..2 run return 0
# side pockets: |c - L/2| <= $side_open
scoreboard players operation #sweep.m pool.tmp = $L pool.const
scoreboard players operation #sweep.m pool.tmp /= #2 pool.const
scoreboard players operation #sweep.along pool.tmp -= #sweep.m pool.tmp
execute if score #sweep.along pool.tmp matches ..-1 run scoreboard players operation #sweep.along pool.tmp *= #-1 pool.const
execute if score #sweep.along pool.tmp <= $side_open pool.const run scoreboard players set #sweep.pocket pool.tmp 1
