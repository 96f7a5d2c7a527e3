# as the new body: its id, its place on a 16 x 16 grid 1.5 blocks apart, its heading, its tags
tag @s remove phys.new
scoreboard players operation @s phys.id = #i phys.tmp
scoreboard players operation @s phys.x = @s phys.id
scoreboard players operation @s phys.x %= #16 phys.const
scoreboard players operation @s phys.x *= #1500 phys.const
scoreboard players operation @s phys.z = @s phys.id
scoreboard players operation @s phys.z /= #16 phys.const
scoreboard players operation @s phys.z *= #1500 phys.const
execute store result entity @s Pos[0] double 0.001 run scoreboard players get @s phys.x
execute store result entity @s Pos[2] double 0.001 run scoreboard players get @s phys.z
scoreboard players operation @s phys.yaw = @s phys.id
scoreboard players operation @s phys.yaw *= #37 phys.const
scoreboard players operation @s phys.yaw %= #360 phys.const
execute store result entity @s Rotation[0] float 1 run scoreboard players get @s phys.yaw
scoreboard players operation @s phys.energy = @s phys.id
scoreboard players operation @s phys.energy %= #37 phys.const
scoreboard players set @s phys.hits 0
scoreboard players set @s phys.age 0
scoreboard players set @s phys.size 1
function phys:setup/tags
