# pool:physics/find/ball — earliest event of the moving ball @s in this sub-step: a rail or pocket
# on its chord, or a contact with another ball; improves #best #kind and the event tags.
# Reads: @s pool.id pool.cx pool.cz pool.x pool.z (chord) pool.lx pool.hx pool.lz pool.hz (its box),
# #best pool.tmp.
# Writes: #best #kind (1 balls, 2 cushion, 3 pocket) #rail pool.tmp, tags pool.event (@s or the
# first ball) and pool.event_b (the other ball); #a.* chord copies.
scoreboard players operation #a.id pool.tmp = @s pool.id
scoreboard players operation #a.bx pool.tmp = @s pool.cx
scoreboard players operation #a.bz pool.tmp = @s pool.cz
scoreboard players operation #a.ex pool.tmp = @s pool.x
scoreboard players operation #a.ez pool.tmp = @s pool.z
scoreboard players operation #a.lx pool.tmp = @s pool.lx
scoreboard players operation #a.hx pool.tmp = @s pool.hx
scoreboard players operation #a.lz pool.tmp = @s pool.lz
scoreboard players operation #a.hz pool.tmp = @s pool.hz
function pool:physics/sweep/rails
execute if score #rf pool.tmp < #best pool.tmp run function pool:physics/find/rail_event
tag @s add pool.self
execute as @e[tag=pool.moving,tag=!pool.self] if score @s pool.id > #a.id pool.tmp run function pool:physics/find/pair
execute as @e[tag=pool.ball,tag=!pool.moving,scores={pool.state=0}] run function pool:physics/find/pair
tag @s remove pool.self
