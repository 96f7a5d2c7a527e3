# pool:ball/roll/direction — $out = round(10^7 $a / spd): a velocity component over the speed,
# x 100000, by long division (each remainder times 10 stays below 2^31).
# Reads: $a pool.math (|$a| <= 2000000 um/tick); @s pool.spd (> 0, 0.01 um/tick).
# Writes: $out pool.math; temporaries #n #d pool.tmp.
scoreboard players operation #n pool.tmp = $a pool.math
execute if score #n pool.tmp matches ..-1 run scoreboard players operation #n pool.tmp *= #-1 pool.const
scoreboard players operation #n pool.tmp *= #1000 pool.const
scoreboard players operation $out pool.math = #n pool.tmp
scoreboard players operation $out pool.math /= @s pool.spd
scoreboard players operation #n pool.tmp %= @s pool.spd
function pool:ball/roll/direction_digit
function pool:ball/roll/direction_digit
function pool:ball/roll/direction_digit
function pool:ball/roll/direction_digit
# round: add 1 when the remainder is at least half the divisor
scoreboard players operation #n pool.tmp *= #2 pool.const
execute if score #n pool.tmp >= @s pool.spd run scoreboard players add $out pool.math 1
execute if score $a pool.math matches ..-1 run scoreboard players operation $out pool.math *= #-1 pool.const
