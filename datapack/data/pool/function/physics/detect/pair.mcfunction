# pool:physics/detect/pair — the contact of ball @s (b) with the ball tagged pool.self (a)
# (pool:physics/detect/pair/contact) becomes a's event if it is the earliest so far.
# Reads: #best pool.tmp. Writes: #best (absolute time) #kind #partner pool.tmp.
execute unless function pool:physics/detect/pair/contact run return 0
execute if score #t pool.tmp >= #best pool.tmp run return 0
scoreboard players operation #best pool.tmp = #t pool.tmp
scoreboard players set #kind pool.tmp 1
scoreboard players operation #partner pool.tmp = @s pool.id
