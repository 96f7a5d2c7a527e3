# pool:math/isqrt gives floor(sqrt($in)): around perfect squares, at the int32 maximum, 0 for n <= 0.
scoreboard players set $in pool.math 17
function pool:math/isqrt
assert score $out pool.math matches 4
scoreboard players set $in pool.math 16
function pool:math/isqrt
assert score $out pool.math matches 4
scoreboard players set $in pool.math 15
function pool:math/isqrt
assert score $out pool.math matches 3
scoreboard players set $in pool.math 2147395599
function pool:math/isqrt
assert score $out pool.math matches 46339
scoreboard players set $in pool.math 2147395600
function pool:math/isqrt
assert score $out pool.math matches 46340
scoreboard players set $in pool.math 2147483647
function pool:math/isqrt
assert score $out pool.math matches 46340
scoreboard players set $in pool.math 0
function pool:math/isqrt
assert score $out pool.math matches 0
scoreboard players set $in pool.math -7
function pool:math/isqrt
assert score $out pool.math matches 0
