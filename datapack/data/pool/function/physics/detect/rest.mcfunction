# pool:physics/detect/rest — the ball @s at rest has a new chord (a point: it was rewound to an
# event and stayed at rest): it offers its contacts to the moving balls that keep their chords (the
# fresh moving balls test it in their own search).
# Reads: @s pool.id, box. Writes: the offered balls' stored events; #cost.work #pair.a.* pool.tmp.
scoreboard players add #cost.work pool.tmp 60
function pool:physics/detect/pair/self
execute as @e[tag=pool.moving,tag=!pool.fresh] run function pool:physics/detect/pair/offer
tag @s remove pool.self
