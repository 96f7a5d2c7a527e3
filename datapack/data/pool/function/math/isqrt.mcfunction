# pool:math/isqrt — exact integer square root floor(sqrt($in)) for 0 <= $in <= 2147483647.
# Reads: $in pool.math. Writes: $out pool.math; temporaries #isqrt.x #isqrt.y pool.math.
# Newton's step x <- (x + n/x) / 2 from a start 2^(k+1) >= sqrt(n), n in [4^k, 4^(k+1)).
# From above the floor iterates fall monotonically to floor(sqrt(n)); four steps bring any
# start within ratio 2 to below floor+1, the fifth (kept by "min") removes the last overshoot.
# Negative input gives 0. Cost: 31 to 46 commands (fewer for large n).
scoreboard players set $out pool.math 0
execute if score $in pool.math matches ..0 run return 0
function pool:math/isqrt/start
scoreboard players operation #isqrt.y pool.math = $in pool.math
scoreboard players operation #isqrt.y pool.math /= #isqrt.x pool.math
scoreboard players operation #isqrt.y pool.math += #isqrt.x pool.math
scoreboard players operation #isqrt.y pool.math /= #2 pool.const
scoreboard players operation #isqrt.x pool.math < #isqrt.y pool.math
scoreboard players operation #isqrt.y pool.math = $in pool.math
scoreboard players operation #isqrt.y pool.math /= #isqrt.x pool.math
scoreboard players operation #isqrt.y pool.math += #isqrt.x pool.math
scoreboard players operation #isqrt.y pool.math /= #2 pool.const
scoreboard players operation #isqrt.x pool.math < #isqrt.y pool.math
scoreboard players operation #isqrt.y pool.math = $in pool.math
scoreboard players operation #isqrt.y pool.math /= #isqrt.x pool.math
scoreboard players operation #isqrt.y pool.math += #isqrt.x pool.math
scoreboard players operation #isqrt.y pool.math /= #2 pool.const
scoreboard players operation #isqrt.x pool.math < #isqrt.y pool.math
scoreboard players operation #isqrt.y pool.math = $in pool.math
scoreboard players operation #isqrt.y pool.math /= #isqrt.x pool.math
scoreboard players operation #isqrt.y pool.math += #isqrt.x pool.math
scoreboard players operation #isqrt.y pool.math /= #2 pool.const
scoreboard players operation #isqrt.x pool.math < #isqrt.y pool.math
scoreboard players operation #isqrt.y pool.math = $in pool.math
scoreboard players operation #isqrt.y pool.math /= #isqrt.x pool.math
scoreboard players operation #isqrt.y pool.math += #isqrt.x pool.math
scoreboard players operation #isqrt.y pool.math /= #2 pool.const
scoreboard players operation #isqrt.x pool.math < #isqrt.y pool.math
scoreboard players operation $out pool.math = #isqrt.x pool.math
