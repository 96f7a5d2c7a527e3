# pool:physics/detect/sweep/pair_reject — #sweep.apart = 1 when d0 . D >= 0 component by component:
# the balls separate (or keep their distance) all through the interval. A cheap test before the
# exact one.
# Reads: #sweep.dx #sweep.dz pool.tmp (d0), $x $z pool.math (D). Writes: #sweep.apart pool.tmp.
scoreboard players set #sweep.apart pool.tmp 1
execute if score #sweep.dx pool.tmp matches 0.. if score $x pool.math matches 0.. if score #sweep.dz pool.tmp matches 0.. if score $z pool.math matches 0.. run return 0
execute if score #sweep.dx pool.tmp matches 0.. if score $x pool.math matches 0.. if score #sweep.dz pool.tmp matches ..0 if score $z pool.math matches ..0 run return 0
execute if score #sweep.dx pool.tmp matches ..0 if score $x pool.math matches ..0 if score #sweep.dz pool.tmp matches 0.. if score $z pool.math matches 0.. run return 0
execute if score #sweep.dx pool.tmp matches ..0 if score $x pool.math matches ..0 if score #sweep.dz pool.tmp matches ..0 if score $z pool.math matches ..0 run return 0
scoreboard players set #sweep.apart pool.tmp 0
