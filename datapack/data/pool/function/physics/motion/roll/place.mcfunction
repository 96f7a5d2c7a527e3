# pool:physics/motion/roll/place — position and velocity of a rolling @s from its phase scores:
# r = r0 + d s, v = w = d spd (rounded to um and um/tick).
# Reads: @s pool.x0 pool.z0 pool.dx pool.dz pool.s pool.spd.
# Writes: @s pool.x pool.z pool.vx pool.vz pool.wx pool.wz; the math library's temporaries.
scoreboard players operation $a pool.math = @s pool.s
scoreboard players operation $b pool.math = #100 pool.const
function pool:math/div_round
scoreboard players operation $a pool.math = $out pool.math
scoreboard players operation $b pool.math = @s pool.dx
function pool:math/mul_1e5
scoreboard players operation @s pool.x = @s pool.x0
scoreboard players operation @s pool.x += $out pool.math
scoreboard players operation $b pool.math = @s pool.dz
function pool:math/mul_1e5
scoreboard players operation @s pool.z = @s pool.z0
scoreboard players operation @s pool.z += $out pool.math
scoreboard players operation $a pool.math = @s pool.spd
scoreboard players operation $b pool.math = #100 pool.const
function pool:math/div_round
scoreboard players operation $a pool.math = $out pool.math
scoreboard players operation $b pool.math = @s pool.dx
function pool:math/mul_1e5
scoreboard players operation @s pool.vx = $out pool.math
scoreboard players operation @s pool.wx = $out pool.math
scoreboard players operation $b pool.math = @s pool.dz
function pool:math/mul_1e5
scoreboard players operation @s pool.vz = $out pool.math
scoreboard players operation @s pool.wz = $out pool.math
