# pool:physics/detect/ball — the earliest event of the moving ball @s, which has a new chord
# (pool.fresh) or whose stored event involved the last event's balls (pool.stale), as the first of a
# pair: a rail or pocket on its chord, or a contact with a ball after it (moving with a larger
# pool.id, or at rest). A fresh ball also offers its contacts to the moving balls before it that
# keep their chords (pool:physics/detect/pair/offer): their stored events stay valid otherwise, so
# they need no search of their own.
# Reads: @s pool.id, chord, box. Writes: @s pool.nt pool.nk pool.nr pool.np (and the offered
# balls'); tag pool.stale removed (pool:physics/detect/store); #cost.work #pair.a.* #detect.best
# #detect.kind #detect.rail #detect.partner pool.tmp.
# charged to #cost.work: 140 commands, 220 to 350 per exact sweep (pool:physics/detect/pair/contact)
scoreboard players add #cost.work pool.tmp 140
function pool:physics/detect/pair/self
scoreboard players set #detect.best pool.tmp 20000
scoreboard players set #detect.kind pool.tmp 0
# rails only when the chord ends beyond a rail line: x outside R..L-R or z outside R..W-R
execute unless score @s pool.x matches 28575..2511425 run function pool:physics/detect/rails
execute if score @s pool.x matches 28575..2511425 unless score @s pool.z matches 28575..1241425 run function pool:physics/detect/rails
execute as @e[tag=pool.moving,tag=!pool.self] if score @s pool.id > #pair.a.id pool.tmp run function pool:physics/detect/pair
execute as @e[tag=pool.ball,tag=!pool.moving,scores={pool.state=0}] run function pool:physics/detect/pair
execute if entity @s[tag=pool.fresh] as @e[tag=pool.moving,tag=!pool.fresh] if score @s pool.id < #pair.a.id pool.tmp run function pool:physics/detect/pair/offer
tag @s remove pool.self
function pool:physics/detect/store
