# pool:physics/resolve/ball_ball/collide — elastic collision of @s (ball a) with ball b (errata 3.x):
# n = (r_b - r_a)/|r_b - r_a|, s = (v_a - v_b) . n; if s > 0: v_a -= s n, v_b += s n.
# The same integer impulse goes to both balls, so momentum is conserved exactly. Spins unchanged.
# Reads: @s pool.x pool.z pool.vx pool.vz; #b.x #b.z #b.vx #b.vz pool.tmp.
# Writes: @s pool.vx pool.vz, #b.vx #b.vz pool.tmp, #hit pool.tmp (1 when they collided, else 0);
# temporaries #jx #jz pool.tmp and the math library's. The caller starts both balls' new phases.
scoreboard players set #hit pool.tmp 0
scoreboard players operation $x pool.math = #b.x pool.tmp
scoreboard players operation $x pool.math -= @s pool.x
scoreboard players operation $z pool.math = #b.z pool.tmp
scoreboard players operation $z pool.math -= @s pool.z
function pool:math/normalize
scoreboard players operation $a pool.math = @s pool.vx
scoreboard players operation $a pool.math -= #b.vx pool.tmp
scoreboard players operation $b pool.math = $ux pool.math
function pool:math/mul_unit
scoreboard players operation #jx pool.tmp = $out pool.math
scoreboard players operation $a pool.math = @s pool.vz
scoreboard players operation $a pool.math -= #b.vz pool.tmp
scoreboard players operation $b pool.math = $uz pool.math
function pool:math/mul_unit
scoreboard players operation #jx pool.tmp += $out pool.math
execute if score #jx pool.tmp matches ..0 run return 0
scoreboard players set #hit pool.tmp 1
# impulse s n
scoreboard players operation $a pool.math = #jx pool.tmp
function pool:math/mul_unit
scoreboard players operation #jz pool.tmp = $out pool.math
scoreboard players operation $b pool.math = $ux pool.math
function pool:math/mul_unit
scoreboard players operation #jx pool.tmp = $out pool.math
scoreboard players operation @s pool.vx -= #jx pool.tmp
scoreboard players operation @s pool.vz -= #jz pool.tmp
scoreboard players operation #b.vx pool.tmp += #jx pool.tmp
scoreboard players operation #b.vz pool.tmp += #jz pool.tmp
