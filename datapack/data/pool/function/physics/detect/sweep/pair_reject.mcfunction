# pool:physics/detect/sweep/pair_reject — #apart = 1 when d0 . D >= 0 component by component: the balls
# separate (or keep their distance) all through the interval. A cheap test before the exact one.
# Reads: #dx #dz pool.tmp (d0), $x $z pool.math (D). Writes: #apart pool.tmp.
scoreboard players set #apart pool.tmp 1
execute if score #dx pool.tmp matches 0.. if score $x pool.math matches 0.. if score #dz pool.tmp matches 0.. if score $z pool.math matches 0.. run return 0
execute if score #dx pool.tmp matches 0.. if score $x pool.math matches 0.. if score #dz pool.tmp matches ..0 if score $z pool.math matches ..0 run return 0
execute if score #dx pool.tmp matches ..0 if score $x pool.math matches ..0 if score #dz pool.tmp matches 0.. if score $z pool.math matches 0.. run return 0
execute if score #dx pool.tmp matches ..0 if score $x pool.math matches ..0 if score #dz pool.tmp matches ..0 if score $z pool.math matches ..0 run return 0
scoreboard players set #apart pool.tmp 0
