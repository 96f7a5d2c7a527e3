# pool:table/read_origin — the marker @s marks the table corner: store its position in mm.
# Reads: @s Pos. Writes: $origin.x $origin.y $origin.z pool.game.
execute store result score $origin.x pool.game run data get entity @s Pos[0] 1000
execute store result score $origin.y pool.game run data get entity @s Pos[1] 1000
execute store result score $origin.z pool.game run data get entity @s Pos[2] 1000
