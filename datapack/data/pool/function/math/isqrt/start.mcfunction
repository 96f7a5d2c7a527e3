# pool:math/isqrt/start — #isqrt.x = 2^(k+1) for $in in [4^k, 4^(k+1)), largest ranges first.
# Reads: $in pool.math (> 0). Writes: #isqrt.x pool.math.
execute if score $in pool.math matches 1073741824.. run return run scoreboard players set #isqrt.x pool.math 65536
execute if score $in pool.math matches 268435456.. run return run scoreboard players set #isqrt.x pool.math 32768
execute if score $in pool.math matches 67108864.. run return run scoreboard players set #isqrt.x pool.math 16384
execute if score $in pool.math matches 16777216.. run return run scoreboard players set #isqrt.x pool.math 8192
execute if score $in pool.math matches 4194304.. run return run scoreboard players set #isqrt.x pool.math 4096
execute if score $in pool.math matches 1048576.. run return run scoreboard players set #isqrt.x pool.math 2048
execute if score $in pool.math matches 262144.. run return run scoreboard players set #isqrt.x pool.math 1024
execute if score $in pool.math matches 65536.. run return run scoreboard players set #isqrt.x pool.math 512
execute if score $in pool.math matches 16384.. run return run scoreboard players set #isqrt.x pool.math 256
execute if score $in pool.math matches 4096.. run return run scoreboard players set #isqrt.x pool.math 128
execute if score $in pool.math matches 1024.. run return run scoreboard players set #isqrt.x pool.math 64
execute if score $in pool.math matches 256.. run return run scoreboard players set #isqrt.x pool.math 32
execute if score $in pool.math matches 64.. run return run scoreboard players set #isqrt.x pool.math 16
execute if score $in pool.math matches 16.. run return run scoreboard players set #isqrt.x pool.math 8
execute if score $in pool.math matches 4.. run return run scoreboard players set #isqrt.x pool.math 4
scoreboard players set #isqrt.x pool.math 2
