# pool:math/sincos: exact at right angles, within 1 unit (x 10000) elsewhere, any int angle in centidegrees.
scoreboard players set $a pool.math 0
function pool:math/sincos
assert score $sin pool.math matches 0
assert score $cos pool.math matches 10000
scoreboard players set $a pool.math 9000
function pool:math/sincos
assert score $sin pool.math matches 10000
assert score $cos pool.math matches 0
scoreboard players set $a pool.math -9000
function pool:math/sincos
assert score $sin pool.math matches -10000
assert score $cos pool.math matches 0
# 30 degrees: sin 5000, cos 8660.25
scoreboard players set $a pool.math 3000
function pool:math/sincos
assert score $sin pool.math matches 4999..5001
assert score $cos pool.math matches 8659..8661
# 390 degrees wraps to 30
scoreboard players set $a pool.math 39000
function pool:math/sincos
assert score $sin pool.math matches 4999..5001
assert score $cos pool.math matches 8659..8661
