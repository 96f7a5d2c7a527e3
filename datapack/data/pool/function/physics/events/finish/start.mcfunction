# pool:physics/events/finish/start — the physics tick's events are all resolved: its searches are
# used up and the separation passes begin. Writes: #events.finishing #separate.passes pool.tmp; tags
# pool.found pool.fresh (removed), pool.touch (removed from pocketed balls).
scoreboard players set #events.finishing pool.tmp 1
scoreboard players set #separate.passes pool.tmp 0
tag @e[tag=pool.found] remove pool.found
tag @e[tag=pool.fresh] remove pool.fresh
tag @e[tag=pool.touch,scores={pool.state=3}] remove pool.touch
