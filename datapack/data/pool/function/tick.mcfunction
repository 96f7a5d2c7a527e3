# pool:tick — player controls, then one physics step while any ball moves. Runs from #minecraft:tick.
# Reads: $resting pool.game, players' pool.power. Writes: through pool:controls/tick, pool:physics/step.
function pool:controls/tick
execute if score $resting pool.game matches 0 run function pool:physics/step
