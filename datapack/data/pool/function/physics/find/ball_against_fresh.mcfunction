# pool:physics/find/ball_against_fresh — @s keeps its stored event and tests only the balls with
# a new chord (pool.fresh) that come after it. Reads/writes: as pool:physics/find/ball.
scoreboard players operation #best pool.tmp = @s pool.nt
scoreboard players operation #kind pool.tmp = @s pool.nk
scoreboard players operation #event_rail pool.tmp = @s pool.nr
scoreboard players operation #partner pool.tmp = @s pool.np
tag @s add pool.self
execute as @e[tag=pool.moving,tag=pool.fresh,tag=!pool.self] if score @s pool.id > #a.id pool.tmp run function pool:physics/find/pair
execute as @e[tag=pool.ball,tag=pool.fresh,tag=!pool.moving,scores={pool.state=0}] run function pool:physics/find/pair
tag @s remove pool.self
function pool:physics/find/store
