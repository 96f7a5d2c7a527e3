# pool:math/atan2 — angle of the vector (x, z) in centidegrees, -18000 < $out <= 18000,
# counter-clockwise from +x towards +z; 0 for the zero vector.
# Reads: $x $z pool.math (|x|, |z| < 2^30). Writes: $out pool.math (error <= 1 centidegree);
# temporaries #normalize.nx #normalize.nz #normalize.m #normalize.d #atan2.y #atan2.w #atan2.p
# pool.math.
# Octant reduction to w = min/max in [0, 1], then atan w by a degree-9 odd polynomial
# (Abramowitz-Stegun 4.4.49, |error| <= 1e-5 rad).
scoreboard players operation #normalize.nx pool.math = $x pool.math
scoreboard players operation #normalize.nz pool.math = $z pool.math
execute if score #normalize.nx pool.math matches ..-1 run scoreboard players operation #normalize.nx pool.math *= #-1 pool.const
execute if score #normalize.nz pool.math matches ..-1 run scoreboard players operation #normalize.nz pool.math *= #-1 pool.const
scoreboard players operation #normalize.m pool.math = #normalize.nx pool.math
scoreboard players operation #normalize.m pool.math > #normalize.nz pool.math
scoreboard players set $out pool.math 0
execute if score #normalize.m pool.math matches 0 run return 0
execute if score #normalize.m pool.math matches 32768.. run function pool:math/normalize/shrink
# w = min * 10000 / max, rounded
scoreboard players operation #atan2.w pool.math = #normalize.nx pool.math
scoreboard players operation #atan2.w pool.math < #normalize.nz pool.math
scoreboard players operation #normalize.m pool.math = #normalize.nx pool.math
scoreboard players operation #normalize.m pool.math > #normalize.nz pool.math
scoreboard players operation #atan2.w pool.math *= #20000 pool.const
scoreboard players operation #atan2.w pool.math += #normalize.m pool.math
scoreboard players operation #normalize.m pool.math *= #2 pool.const
scoreboard players operation #atan2.w pool.math /= #normalize.m pool.math
function pool:math/atan2/series
# unfold the octants
execute if score #normalize.nz pool.math > #normalize.nx pool.math run scoreboard players operation $out pool.math *= #-1 pool.const
execute if score #normalize.nz pool.math > #normalize.nx pool.math run scoreboard players add $out pool.math 9000
execute if score $x pool.math matches ..-1 run scoreboard players operation $out pool.math *= #-1 pool.const
execute if score $x pool.math matches ..-1 run scoreboard players add $out pool.math 18000
execute if score $z pool.math matches ..-1 run scoreboard players operation $out pool.math *= #-1 pool.const
