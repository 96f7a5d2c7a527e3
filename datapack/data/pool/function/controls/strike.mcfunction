# pool:controls/strike — the player @s strikes: angle from the view's yaw, speed from pool.power.
# Minecraft's yaw 0 faces +z and 90 faces -x, so the table angle is yaw + 90 degrees.
# Reads: @s Rotation[0], @s pool.power. Writes: #api.* pool.tmp, @s pool.power (0); the shot.
execute store result score #api.angle pool.tmp run data get entity @s Rotation[0] 100
scoreboard players add #api.angle pool.tmp 9000
scoreboard players operation #api.speed pool.tmp = @s pool.power
scoreboard players set #controls.d pool.tmp 100
scoreboard players operation #api.speed pool.tmp < #controls.d pool.tmp
scoreboard players set #controls.d pool.tmp 65
scoreboard players operation #api.speed pool.tmp *= #controls.d pool.tmp
scoreboard players set #api.tip_x pool.tmp 0
scoreboard players set #api.tip_y pool.tmp 0
scoreboard players set #api.elevation pool.tmp 0
scoreboard players set @s pool.power 0
function pool:api/shot/apply
