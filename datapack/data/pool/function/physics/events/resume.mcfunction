# pool:physics/events/resume — after its event @s goes on from #events.now: save that state and mark
# it dirty.
# Reads: #events.now pool.tmp. Writes: @s saved scores, tag pool.dirty.
function pool:physics/events/save
tag @s add pool.dirty
