# pool:math/div_round — $out = round($a / $b), halves away from zero (mirror-symmetric).
# Reads: $a pool.math (|$a| < 2^31 - $b/2), $b pool.math > 0. Writes: $out pool.math; temporary
# #div_round.a.
scoreboard players operation #div_round.a pool.math = $a pool.math
execute if score #div_round.a pool.math matches ..-1 run scoreboard players operation #div_round.a pool.math *= #-1 pool.const
scoreboard players operation $out pool.math = $b pool.math
scoreboard players operation $out pool.math /= #2 pool.const
scoreboard players operation $out pool.math += #div_round.a pool.math
scoreboard players operation $out pool.math /= $b pool.math
execute if score $a pool.math matches ..-1 run scoreboard players operation $out pool.math *= #-1 pool.const
