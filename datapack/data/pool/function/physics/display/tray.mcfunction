# pool:physics/display/tray — show pocketed @s in the ball return: a row 120 mm outside the table's
# z = 0 cushion line, the N-th ball pocketed ($pocketed) at x = 60 N mm from the corner, at the
# balls' height (Pos[1] is kept). Stores into Pos only, so the pocket needs no entity NBT merge.
# Reads: $pocketed $origin.x $origin.z pool.game. Writes: @s Pos; temporaries #display.p #display.q
# pool.tmp.
scoreboard players set #display.q pool.tmp 60
scoreboard players operation #display.p pool.tmp = $pocketed pool.game
scoreboard players operation #display.p pool.tmp *= #display.q pool.tmp
scoreboard players operation #display.p pool.tmp += $origin.x pool.game
execute store result entity @s Pos[0] double 0.001 run scoreboard players get #display.p pool.tmp
scoreboard players set #display.p pool.tmp -120
scoreboard players operation #display.p pool.tmp += $origin.z pool.game
execute store result entity @s Pos[2] double 0.001 run scoreboard players get #display.p pool.tmp
