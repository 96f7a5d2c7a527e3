# pool:physics/resolve/cushion/newton — the sliding ball's acceleration in
# pool:physics/resolve/cushion/cross: with f(dt) = p + vo dt + ao dt^2 / 2 (ao = -a . n, outwards)
# and dt0 = -p / vo, dt -= f(dt0) / f'(dt0), where f(dt0) = ao dt0^2 / 2 and f' = vo + ao dt0 (dt in
# 1e-4 tick).
# Reads: #cushion.dt #cushion.vo #cushion.nx #cushion.nz pool.tmp (|dt| <= 5000), @s pool.ax pool.az.
# Writes: #cushion.dt #cushion.ao #cushion.g #cushion.d pool.tmp and the math library's temporaries.
scoreboard players operation #cushion.ao pool.tmp = @s pool.ax
scoreboard players operation #cushion.ao pool.tmp *= #cushion.nx pool.tmp
scoreboard players operation #cushion.d pool.tmp = @s pool.az
scoreboard players operation #cushion.d pool.tmp *= #cushion.nz pool.tmp
scoreboard players operation #cushion.ao pool.tmp += #cushion.d pool.tmp
scoreboard players operation #cushion.ao pool.tmp *= #-1 pool.const
# in um/tick^2 (pool.ax pool.az are in 0.001 um/tick^2)
scoreboard players operation $a pool.math = #cushion.ao pool.tmp
scoreboard players operation $b pool.math = #1000 pool.const
function pool:math/div_round
scoreboard players operation #cushion.ao pool.tmp = $out pool.math
# f(dt0) in um: ao g / 20000 with g = dt0^2 / 10000
scoreboard players operation #cushion.g pool.tmp = #cushion.dt pool.tmp
scoreboard players operation #cushion.g pool.tmp *= #cushion.dt pool.tmp
scoreboard players operation #cushion.g pool.tmp /= #10000 pool.const
scoreboard players operation $a pool.math = #cushion.ao pool.tmp
scoreboard players operation $a pool.math *= #cushion.g pool.tmp
scoreboard players operation $b pool.math = #20000 pool.const
function pool:math/div_round
scoreboard players operation #cushion.g pool.tmp = $out pool.math
# f' = vo + ao dt0 / 10000
scoreboard players operation $a pool.math = #cushion.ao pool.tmp
scoreboard players operation $b pool.math = #cushion.dt pool.tmp
function pool:math/mul_unit
scoreboard players operation $b pool.math = #cushion.vo pool.tmp
scoreboard players operation $b pool.math += $out pool.math
execute if score $b pool.math matches ..0 run return 0
scoreboard players operation $a pool.math = #cushion.g pool.tmp
function pool:math/div_1e4
scoreboard players operation #cushion.dt pool.tmp -= $out pool.math
