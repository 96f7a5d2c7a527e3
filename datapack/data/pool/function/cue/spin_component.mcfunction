# pool:cue/spin_component — $out = (5/2) V P / 10^7 for the cue strike's spin factors.
# Reads: #cue.v pool.tmp (V, um/tick), #cue.p pool.tmp (P in 1e-7, |P| <= 10^7). Writes: $out
# pool.math.
scoreboard players operation $a pool.math = #cue.p pool.tmp
scoreboard players operation $b pool.math = #1000 pool.const
function pool:math/div_round
scoreboard players operation $b pool.math = $out pool.math
scoreboard players operation $a pool.math = #cue.v pool.tmp
function pool:math/mul_unit
scoreboard players operation $a pool.math = $out pool.math
scoreboard players operation $a pool.math *= #5 pool.const
scoreboard players operation $b pool.math = #2 pool.const
function pool:math/div_round
