# pool:physics/detect/pair — the contact of ball @s (b) with the ball tagged pool.self (a)
# (pool:physics/detect/pair/contact) becomes a's event if it is the earliest so far.
# Reads: #detect.best pool.tmp. Writes: #detect.best (absolute time) #detect.kind #detect.partner
# pool.tmp.
execute unless function pool:physics/detect/pair/contact run return 0
execute if score #detect.t pool.tmp >= #detect.best pool.tmp run return 0
scoreboard players operation #detect.best pool.tmp = #detect.t pool.tmp
scoreboard players set #detect.kind pool.tmp 1
scoreboard players operation #detect.partner pool.tmp = @s pool.id
