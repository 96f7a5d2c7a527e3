# as and at a body past a wall: turn around
tp @s ~ ~ ~ ~180 ~
execute store result score @s phys.yaw run data get entity @s Rotation[0] 1
