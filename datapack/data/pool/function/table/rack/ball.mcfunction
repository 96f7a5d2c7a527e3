# pool:table/rack/ball — summon ball $(id) at rest at ($(x), $(z)) um, shown as $(item).
# Macro arguments: id, x, z (um, table frame), item (an item id). Writes: the new ball's scores.
$summon item_display ~ ~ ~ {Tags:["pool.ball","pool.new"],teleport_duration:1,item:{id:"$(item)",count:1},transformation:{left_rotation:[0f,0f,0f,1f],right_rotation:[0f,0f,0f,1f],translation:[0f,0f,0f],scale:[0.057f,0.057f,0.057f]}}
$scoreboard players set @e[tag=pool.new] pool.id $(id)
$scoreboard players set @e[tag=pool.new] pool.x $(x)
$scoreboard players set @e[tag=pool.new] pool.z $(z)
execute as @e[tag=pool.new] run function pool:physics/motion/roll/stop
scoreboard players set @e[tag=pool.new] pool.wy 0
execute as @e[tag=pool.new] run function pool:physics/display/place
tag @e[tag=pool.new] remove pool.new
