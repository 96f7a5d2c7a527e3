# pool:physics/find/ball — the earliest event of the moving ball @s as the first of a pair: a rail
# or pocket on its chord, or a contact with a ball after it (moving with a larger pool.id, or at
# rest). A ball with a new chord (pool.fresh) or whose stored event involved the last event's balls
# (pool.stale) is tested against all; any other keeps its stored event, still valid since its
# chord and its partner's are unchanged, and is tested only against the fresh balls.
# Reads: @s pool.id, chord, box and stored event. Writes: @s pool.nt pool.nk pool.nr pool.np;
# tag pool.stale removed (pool:physics/find/store); #work #a.* #best #kind #event_rail #partner pool.tmp.
scoreboard players operation #a.id pool.tmp = @s pool.id
scoreboard players operation #a.lx pool.tmp = @s pool.lx
scoreboard players operation #a.hx pool.tmp = @s pool.hx
scoreboard players operation #a.lz pool.tmp = @s pool.lz
scoreboard players operation #a.hz pool.tmp = @s pool.hz
# charged to #work: 40 commands, 100 more for a search against all, 280 per exact sweep (find/pair)
scoreboard players add #work pool.tmp 40
execute if entity @s[tag=!pool.fresh,tag=!pool.stale] run return run function pool:physics/find/ball_against_fresh
scoreboard players add #work pool.tmp 100
scoreboard players set #best pool.tmp 20000
scoreboard players set #kind pool.tmp 0
# rails only when the chord ends beyond a rail line: x outside R..L-R or z outside R..W-R
execute unless score @s pool.x matches 28575..2511425 run function pool:physics/find/rails
execute if score @s pool.x matches 28575..2511425 unless score @s pool.z matches 28575..1241425 run function pool:physics/find/rails
tag @s add pool.self
execute as @e[tag=pool.moving,tag=!pool.self] if score @s pool.id > #a.id pool.tmp run function pool:physics/find/pair
execute as @e[tag=pool.ball,tag=!pool.moving,scores={pool.state=0}] run function pool:physics/find/pair
tag @s remove pool.self
function pool:physics/find/store
