# pool:math/isqrt — exact integer square root floor(sqrt($in)) for 0 <= $in <= 2147483647.
# Reads: $in pool.math. Writes: $out pool.math; temporaries #x #y pool.math.
# Newton's step x <- (x + n/x) / 2 from a start 2^(k+1) >= sqrt(n), n in [4^k, 4^(k+1)).
# From above the floor iterates fall monotonically to floor(sqrt(n)); four steps bring any
# start within ratio 2 to below floor+1, the fifth (kept by "min") removes the last overshoot.
# Negative input gives 0. Cost: 45 commands.
scoreboard players set $out pool.math 0
execute if score $in pool.math matches ..0 run return 0
scoreboard players set #x pool.math 2
execute if score $in pool.math matches 4.. run scoreboard players set #x pool.math 4
execute if score $in pool.math matches 16.. run scoreboard players set #x pool.math 8
execute if score $in pool.math matches 64.. run scoreboard players set #x pool.math 16
execute if score $in pool.math matches 256.. run scoreboard players set #x pool.math 32
execute if score $in pool.math matches 1024.. run scoreboard players set #x pool.math 64
execute if score $in pool.math matches 4096.. run scoreboard players set #x pool.math 128
execute if score $in pool.math matches 16384.. run scoreboard players set #x pool.math 256
execute if score $in pool.math matches 65536.. run scoreboard players set #x pool.math 512
execute if score $in pool.math matches 262144.. run scoreboard players set #x pool.math 1024
execute if score $in pool.math matches 1048576.. run scoreboard players set #x pool.math 2048
execute if score $in pool.math matches 4194304.. run scoreboard players set #x pool.math 4096
execute if score $in pool.math matches 16777216.. run scoreboard players set #x pool.math 8192
execute if score $in pool.math matches 67108864.. run scoreboard players set #x pool.math 16384
execute if score $in pool.math matches 268435456.. run scoreboard players set #x pool.math 32768
execute if score $in pool.math matches 1073741824.. run scoreboard players set #x pool.math 65536
scoreboard players operation #y pool.math = $in pool.math
scoreboard players operation #y pool.math /= #x pool.math
scoreboard players operation #y pool.math += #x pool.math
scoreboard players operation #y pool.math /= #2 pool.const
scoreboard players operation #x pool.math < #y pool.math
scoreboard players operation #y pool.math = $in pool.math
scoreboard players operation #y pool.math /= #x pool.math
scoreboard players operation #y pool.math += #x pool.math
scoreboard players operation #y pool.math /= #2 pool.const
scoreboard players operation #x pool.math < #y pool.math
scoreboard players operation #y pool.math = $in pool.math
scoreboard players operation #y pool.math /= #x pool.math
scoreboard players operation #y pool.math += #x pool.math
scoreboard players operation #y pool.math /= #2 pool.const
scoreboard players operation #x pool.math < #y pool.math
scoreboard players operation #y pool.math = $in pool.math
scoreboard players operation #y pool.math /= #x pool.math
scoreboard players operation #y pool.math += #x pool.math
scoreboard players operation #y pool.math /= #2 pool.const
scoreboard players operation #x pool.math < #y pool.math
scoreboard players operation #y pool.math = $in pool.math
scoreboard players operation #y pool.math /= #x pool.math
scoreboard players operation #y pool.math += #x pool.math
scoreboard players operation #y pool.math /= #2 pool.const
scoreboard players operation #x pool.math < #y pool.math
scoreboard players operation $out pool.math = #x pool.math
