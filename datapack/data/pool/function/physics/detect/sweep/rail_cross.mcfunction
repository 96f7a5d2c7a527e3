# pool:physics/detect/sweep/rail_cross — fraction of a chord at which it leaves the side of a line.
# Reads: #c0 #c1 pool.tmp (signed distances of the chord's ends from the line, > 0 inside).
# Writes: #cf pool.tmp = 10000 c0 / (c0 - c1) when c1 < 0 (c0 taken as >= 0), else 10001.
scoreboard players set #cf pool.tmp 10001
execute if score #c1 pool.tmp matches 0.. run return 0
execute if score #c0 pool.tmp matches ..-1 run scoreboard players set #c0 pool.tmp 0
scoreboard players operation $a pool.math = #c0 pool.tmp
scoreboard players operation $b pool.math = #c0 pool.tmp
scoreboard players operation $b pool.math -= #c1 pool.tmp
function pool:math/div_1e4
scoreboard players operation #cf pool.tmp = $out pool.math
