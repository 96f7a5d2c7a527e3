# pool:math/cos_1e5/sin — $out = sin x x 100000 = x (1 - t/6 (1 - t/20 (1 - t/42 (1 - t/72)))) for
# pool:math/cos_1e5's complement x <= pi/4.
# Reads: #cos_1e5.x #cos_1e5.t pool.math, $out = 100000. Writes: $out pool.math; #cos_1e5.k.
scoreboard players set #cos_1e5.k pool.math 72
function pool:math/cos_1e5/horner
scoreboard players set #cos_1e5.k pool.math 42
function pool:math/cos_1e5/horner
scoreboard players set #cos_1e5.k pool.math 20
function pool:math/cos_1e5/horner
scoreboard players set #cos_1e5.k pool.math 6
function pool:math/cos_1e5/horner
scoreboard players operation $a pool.math = #cos_1e5.x pool.math
scoreboard players operation $b pool.math = $out pool.math
function pool:math/mul_1e5
