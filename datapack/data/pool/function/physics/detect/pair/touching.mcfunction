# pool:physics/detect/pair/touching — b (@s) and a (tagged pool.self) touch at once (at #events.now)
# but do not approach, so they are no event; their chords can still converge (a sliding ball's path
# curves), and nothing else looks at this pair again this tick: tag both pool.touch so that
# pool:physics/events/finish pushes them apart at the tick's end if they end up closer than 2R.
# Writes: tag pool.touch on both balls. Returns 0 (no event).
tag @s add pool.touch
tag @e[tag=pool.self] add pool.touch
return 0
