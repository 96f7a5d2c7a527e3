# pool:math/cos_1e5: cos x 100000 within 1 unit for 0..90 degrees, exact at 0 and 90.
scoreboard players set $a pool.math 0
function pool:math/cos_1e5
assert score $out pool.math matches 100000
scoreboard players set $a pool.math 9000
function pool:math/cos_1e5
assert score $out pool.math matches 0
# 60 degrees: 50000
scoreboard players set $a pool.math 6000
function pool:math/cos_1e5
assert score $out pool.math matches 49999..50001
# 89 degrees: 1745.24
scoreboard players set $a pool.math 8900
function pool:math/cos_1e5
assert score $out pool.math matches 1745
# 30 degrees: 86602.5
scoreboard players set $a pool.math 3000
function pool:math/cos_1e5
assert score $out pool.math matches 86601..86604
