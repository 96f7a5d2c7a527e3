# pool:physics/detect/sweep/rail_cross — fraction of a chord at which it leaves the side of a line.
# Reads: #sweep.c0 #sweep.c1 pool.tmp (signed distances of the chord's ends from the line, > 0
# inside).
# Writes: #sweep.cf pool.tmp = 10000 c0 / (c0 - c1) when c1 < 0 (c0 taken as >= 0), else 10001.
scoreboard players set #sweep.cf pool.tmp 10001
execute if score #sweep.c1 pool.tmp matches 0.. run return 0
execute if score #sweep.c0 pool.tmp matches ..-1 run scoreboard players set #sweep.c0 pool.tmp 0
scoreboard players operation $a pool.math = #sweep.c0 pool.tmp
scoreboard players operation $b pool.math = #sweep.c0 pool.tmp
scoreboard players operation $b pool.math -= #sweep.c1 pool.tmp
function pool:math/div_1e4
scoreboard players operation #sweep.cf pool.tmp = $out pool.math
