# pool:physics/detect/rails — rail and pocket test of @s's chord from #events.now to the tick's end.
# Reads/writes: as pool:physics/detect/ball; #sweep.a.bx #sweep.a.bz #sweep.a.ex #sweep.a.ez
# pool.tmp (the chord).
function pool:physics/detect/chord/as_a
function pool:physics/detect/sweep/rails
execute if score #sweep.rf pool.tmp matches 10001 run return 0
scoreboard players operation #sweep.f pool.tmp = #sweep.rf pool.tmp
function pool:physics/detect/absolute
execute if score #detect.t pool.tmp < #detect.best pool.tmp run function pool:physics/detect/rail_event
