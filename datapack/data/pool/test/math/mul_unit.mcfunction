# pool:math/mul_unit: round($a * $b / 10000) half away from zero, exact past the int32 product range.
scoreboard players set $a pool.math 15000
scoreboard players set $b pool.math 1
function pool:math/mul_unit
assert score $out pool.math matches 2
scoreboard players set $a pool.math -15000
function pool:math/mul_unit
assert score $out pool.math matches -2
scoreboard players set $a pool.math 14999
scoreboard players set $b pool.math 1
function pool:math/mul_unit
assert score $out pool.math matches 1
# 123456789 * 7071 / 10000 = 87296295.5... -> 87296296 (the product is far past 2^31)
scoreboard players set $a pool.math 123456789
scoreboard players set $b pool.math 7071
function pool:math/mul_unit
assert score $out pool.math matches 87296296
scoreboard players set $a pool.math -123456789
function pool:math/mul_unit
assert score $out pool.math matches -87296296
