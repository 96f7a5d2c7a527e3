# pool:physics/display/tray — show pocketed @s in the ball return: a row 120 mm outside the table's
# z = 0 cushion line, the N-th ball pocketed ($pocketed) at x = 60 N mm from the corner, at the
# balls' height (Pos[1] is kept). Stores into Pos only, so the pocket needs no entity NBT merge.
# Reads: $pocketed $origin.x $origin.z pool.game. Writes: @s Pos; temporaries #p #q pool.tmp.
scoreboard players set #q pool.tmp 60
scoreboard players operation #p pool.tmp = $pocketed pool.game
scoreboard players operation #p pool.tmp *= #q pool.tmp
scoreboard players operation #p pool.tmp += $origin.x pool.game
execute store result entity @s Pos[0] double 0.001 run scoreboard players get #p pool.tmp
scoreboard players set #p pool.tmp -120
scoreboard players operation #p pool.tmp += $origin.z pool.game
execute store result entity @s Pos[2] double 0.001 run scoreboard players get #p pool.tmp
