# pool:physics/detect/chord/start — move the start of @s's chord along it to time #events.now (the
# chord runs from (cx, cz) at time ct to the tick's end at (x, z), linear in time).
# Reads: #events.now pool.tmp, @s pool.cx pool.cz pool.ct pool.x pool.z. Writes: @s pool.cx pool.cz
# pool.ct.
execute if score @s pool.ct >= #events.now pool.tmp run return 0
scoreboard players operation $a pool.math = #events.now pool.tmp
scoreboard players operation $a pool.math -= @s pool.ct
scoreboard players operation $b pool.math = #10000 pool.const
scoreboard players operation $b pool.math -= @s pool.ct
function pool:math/div_1e4
scoreboard players operation $b pool.math = $out pool.math
scoreboard players operation $a pool.math = @s pool.x
scoreboard players operation $a pool.math -= @s pool.cx
function pool:math/mul_unit
scoreboard players operation @s pool.cx += $out pool.math
scoreboard players operation $a pool.math = @s pool.z
scoreboard players operation $a pool.math -= @s pool.cz
function pool:math/mul_unit
scoreboard players operation @s pool.cz += $out pool.math
scoreboard players operation @s pool.ct = #events.now pool.tmp
