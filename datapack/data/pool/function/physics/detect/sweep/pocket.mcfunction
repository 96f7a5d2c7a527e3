# pool:physics/detect/sweep/pocket — whether the crossing of rail #rail at fraction #rf of the chord
# lies in a pocket opening: within $corner_open of a corner, or $side_open of a long rail's middle.
# Reads: #rail #rf #a.bx #a.bz #a.ex #a.ez pool.tmp. Writes: #pocket pool.tmp; temporaries #c #m.
scoreboard players operation $b pool.math = #rf pool.tmp
execute if score #rail pool.tmp matches 1..2 run scoreboard players operation $a pool.math = #a.ez pool.tmp
execute if score #rail pool.tmp matches 1..2 run scoreboard players operation $a pool.math -= #a.bz pool.tmp
execute if score #rail pool.tmp matches 3..4 run scoreboard players operation $a pool.math = #a.ex pool.tmp
execute if score #rail pool.tmp matches 3..4 run scoreboard players operation $a pool.math -= #a.bx pool.tmp
function pool:math/mul_unit
scoreboard players operation #c pool.tmp = $out pool.math
execute if score #rail pool.tmp matches 1..2 run scoreboard players operation #c pool.tmp += #a.bz pool.tmp
execute if score #rail pool.tmp matches 3..4 run scoreboard players operation #c pool.tmp += #a.bx pool.tmp
# #m = the rail's length: W for the short rails, L for the long ones
execute if score #rail pool.tmp matches 1..2 run scoreboard players operation #m pool.tmp = $W pool.const
execute if score #rail pool.tmp matches 3..4 run scoreboard players operation #m pool.tmp = $L pool.const
execute if score #c pool.tmp <= $corner_open pool.const run scoreboard players set #pocket pool.tmp 1
scoreboard players operation #m pool.tmp -= #c pool.tmp
execute if score #m pool.tmp <= $corner_open pool.const run scoreboard players set #pocket pool.tmp 1
execute if score #rail pool.tmp matches 1..2 run return 0
# side pockets: |c - L/2| <= $side_open
scoreboard players operation #m pool.tmp = $L pool.const
scoreboard players operation #m pool.tmp /= #2 pool.const
scoreboard players operation #c pool.tmp -= #m pool.tmp
execute if score #c pool.tmp matches ..-1 run scoreboard players operation #c pool.tmp *= #-1 pool.const
execute if score #c pool.tmp <= $side_open pool.const run scoreboard players set #pocket pool.tmp 1
