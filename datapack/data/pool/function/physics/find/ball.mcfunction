# pool:physics/find/ball — earliest event of the moving ball @s in this sub-step: a rail or pocket
# on its chord, or a contact with another ball; improves #best #kind and the event tags.
# Reads: @s pool.id, its chord (pool.cx pool.cz pool.ct to pool.x pool.z) and box, #best pool.tmp.
# Writes: #best #kind (1 balls, 2 cushion, 3 pocket) #event_rail pool.tmp, tags pool.event (@s or
# the first ball) and pool.event_b (the other ball); #a.* copies.
scoreboard players operation #a.id pool.tmp = @s pool.id
scoreboard players operation #a.lx pool.tmp = @s pool.lx
scoreboard players operation #a.hx pool.tmp = @s pool.hx
scoreboard players operation #a.lz pool.tmp = @s pool.lz
scoreboard players operation #a.hz pool.tmp = @s pool.hz
# rails only when the chord ends beyond a rail line: x outside R..L-R or z outside R..W-R
execute unless score @s pool.x matches 28575..2511425 run function pool:physics/find/rails
execute if score @s pool.x matches 28575..2511425 unless score @s pool.z matches 28575..1241425 run function pool:physics/find/rails
tag @s add pool.self
execute as @e[tag=pool.moving,tag=!pool.self] if score @s pool.id > #a.id pool.tmp run function pool:physics/find/pair
execute as @e[tag=pool.ball,tag=!pool.moving,scores={pool.state=0}] run function pool:physics/find/pair
tag @s remove pool.self
