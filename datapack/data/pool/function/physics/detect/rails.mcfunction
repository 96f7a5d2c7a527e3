# pool:physics/detect/rails — rail and pocket test of @s's chord from #now to the tick's end.
# Reads/writes: as pool:physics/detect/ball; #a.bx #a.bz #a.ex #a.ez pool.tmp (the chord).
function pool:physics/detect/chord/as_a
function pool:physics/detect/sweep/rails
execute if score #rf pool.tmp matches 10001 run return 0
scoreboard players operation #f pool.tmp = #rf pool.tmp
function pool:physics/detect/absolute
execute if score #t pool.tmp < #best pool.tmp run function pool:physics/detect/rail_event
