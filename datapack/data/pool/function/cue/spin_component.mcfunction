# pool:cue/spin_component — $out = (5/2) V P / 10^8 for the cue strike's spin factors, rounded once
# (halves away from 0, so that mirrored shots get mirrored spins).
# Reads: #cue.v pool.tmp (V, um/tick, <= 21000000), #cue.p pool.tmp (P in 1e-8, |P| <= 5 x 10^7).
# Writes: $out pool.math; temporaries #cue.ph #cue.x pool.tmp and the math library's.
# With |P| = ph 100000 + pl: V |P| / 100000 = V ph + V pl / 100000 (below 2^31 / 5 for V <= 500000).
scoreboard players operation #cue.ph pool.tmp = #cue.p pool.tmp
execute if score #cue.ph pool.tmp matches ..-1 run scoreboard players operation #cue.ph pool.tmp *= #-1 pool.const
scoreboard players operation $b pool.math = #cue.ph pool.tmp
scoreboard players operation $b pool.math %= #100000 pool.const
scoreboard players operation #cue.ph pool.tmp /= #100000 pool.const
scoreboard players operation $a pool.math = #cue.v pool.tmp
function pool:math/mul_1e5
scoreboard players operation #cue.x pool.tmp = #cue.v pool.tmp
scoreboard players operation #cue.x pool.tmp *= #cue.ph pool.tmp
scoreboard players operation #cue.x pool.tmp += $out pool.math
scoreboard players operation $a pool.math = #cue.x pool.tmp
scoreboard players operation $a pool.math *= #5 pool.const
scoreboard players operation $b pool.math = #2000 pool.const
function pool:math/div_round
execute if score #cue.p pool.tmp matches ..-1 run scoreboard players operation $out pool.math *= #-1 pool.const
