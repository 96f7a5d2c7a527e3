# pool:math/normalize — unit vector and length of (x, z).
# Reads: $x $z pool.math (|x|, |z| < 2^30). Writes: $ux $uz pool.math (x 10000, rounded half away
# from 0; both 0 for the zero vector) and $len pool.math (|(x, z)| in the input's unit, within 1
# part in 10000); temporaries #normalize.nx #normalize.nz #normalize.m #normalize.d #normalize.n2
# #normalize.l pool.math, and those of isqrt, mul_unit.
# The magnitudes are rescaled so that the larger one lies in 16384..32767: their squares then
# sum below 2^31 and the direction keeps 15 bits. Signs are put back last (mirror symmetry).
scoreboard players operation #normalize.nx pool.math = $x pool.math
scoreboard players operation #normalize.nz pool.math = $z pool.math
execute if score #normalize.nx pool.math matches ..-1 run scoreboard players operation #normalize.nx pool.math *= #-1 pool.const
execute if score #normalize.nz pool.math matches ..-1 run scoreboard players operation #normalize.nz pool.math *= #-1 pool.const
scoreboard players operation #normalize.m pool.math = #normalize.nx pool.math
scoreboard players operation #normalize.m pool.math > #normalize.nz pool.math
scoreboard players set $ux pool.math 0
scoreboard players set $uz pool.math 0
scoreboard players set $len pool.math 0
execute if score #normalize.m pool.math matches 0 run return 0
execute if score #normalize.m pool.math matches 32768.. run function pool:math/normalize/shrink
execute if score #normalize.m pool.math matches ..16383 run function pool:math/normalize/grow
scoreboard players operation #normalize.n2 pool.math = #normalize.nx pool.math
scoreboard players operation #normalize.n2 pool.math *= #normalize.nx pool.math
scoreboard players operation $in pool.math = #normalize.nz pool.math
scoreboard players operation $in pool.math *= #normalize.nz pool.math
scoreboard players operation $in pool.math += #normalize.n2 pool.math
function pool:math/isqrt
scoreboard players operation #normalize.l pool.math = $out pool.math
scoreboard players operation #normalize.l pool.math *= #2 pool.const
# u = (2 * 10000 * n + l) / (2 l): rounded quotient
scoreboard players operation $ux pool.math = #normalize.nx pool.math
scoreboard players operation $ux pool.math *= #20000 pool.const
scoreboard players operation $ux pool.math += $out pool.math
scoreboard players operation $ux pool.math /= #normalize.l pool.math
scoreboard players operation $uz pool.math = #normalize.nz pool.math
scoreboard players operation $uz pool.math *= #20000 pool.const
scoreboard players operation $uz pool.math += $out pool.math
scoreboard players operation $uz pool.math /= #normalize.l pool.math
execute if score $x pool.math matches ..-1 run scoreboard players operation $ux pool.math *= #-1 pool.const
execute if score $z pool.math matches ..-1 run scoreboard players operation $uz pool.math *= #-1 pool.const
# length = (x, z) . u
scoreboard players operation $a pool.math = $x pool.math
scoreboard players operation $b pool.math = $ux pool.math
function pool:math/mul_unit
scoreboard players operation $len pool.math = $out pool.math
scoreboard players operation $a pool.math = $z pool.math
scoreboard players operation $b pool.math = $uz pool.math
function pool:math/mul_unit
scoreboard players operation $len pool.math += $out pool.math
