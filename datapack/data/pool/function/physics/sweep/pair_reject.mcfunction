# pool:physics/sweep/pair_apart — #apart = 1 when d0 + f D stays beyond 2R in x or in z for every
# f in [0, 1] (both ends on the same side), a cheap reject before the exact test.
# Reads: #dx #dz pool.tmp (d0), $x $z pool.math (D). Writes: #apart pool.tmp; temporaries #e #m.
scoreboard players set #apart pool.tmp 1
scoreboard players operation #e pool.tmp = #dx pool.tmp
scoreboard players operation #e pool.tmp += $x pool.math
scoreboard players operation #m pool.tmp = $2R pool.const
scoreboard players operation #m pool.tmp *= #-1 pool.const
execute if score #dx pool.tmp > $2R pool.const if score #e pool.tmp > $2R pool.const run return 0
execute if score #dx pool.tmp < #m pool.tmp if score #e pool.tmp < #m pool.tmp run return 0
scoreboard players operation #e pool.tmp = #dz pool.tmp
scoreboard players operation #e pool.tmp += $z pool.math
execute if score #dz pool.tmp > $2R pool.const if score #e pool.tmp > $2R pool.const run return 0
execute if score #dz pool.tmp < #m pool.tmp if score #e pool.tmp < #m pool.tmp run return 0
scoreboard players set #apart pool.tmp 0
