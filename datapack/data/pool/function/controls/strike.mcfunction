# pool:controls/strike — the player @s strikes: angle from the view's yaw, speed from pool.power.
# Minecraft's yaw 0 faces +z and 90 faces -x, so the table angle is yaw + 90 degrees.
# Reads: @s Rotation[0], @s pool.power. Writes: #in.* pool.tmp, @s pool.power (0); the shot.
execute store result score #in.angle pool.tmp run data get entity @s Rotation[0] 100
scoreboard players add #in.angle pool.tmp 9000
scoreboard players operation #in.speed pool.tmp = @s pool.power
scoreboard players set #d pool.tmp 100
scoreboard players operation #in.speed pool.tmp < #d pool.tmp
scoreboard players set #d pool.tmp 65
scoreboard players operation #in.speed pool.tmp *= #d pool.tmp
scoreboard players set #in.tip_x pool.tmp 0
scoreboard players set #in.tip_y pool.tmp 0
scoreboard players set #in.elevation pool.tmp 0
scoreboard players set @s pool.power 0
function pool:api/shot/apply
