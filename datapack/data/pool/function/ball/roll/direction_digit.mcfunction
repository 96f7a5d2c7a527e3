# pool:ball/roll/direction_digit — one decimal digit of the long division in pool:ball/roll/direction.
# Reads/writes: $out pool.math (quotient so far), #n pool.tmp (remainder); temporary #d pool.tmp.
scoreboard players operation #n pool.tmp *= #10 pool.const
scoreboard players operation #d pool.tmp = #n pool.tmp
scoreboard players operation #d pool.tmp /= @s pool.spd
scoreboard players operation #n pool.tmp %= @s pool.spd
scoreboard players operation $out pool.math *= #10 pool.const
scoreboard players operation $out pool.math += #d pool.tmp
