# pool:physics/display/place — move the ball's item_display (@s) to its scores: world position in mm
# = table corner ($origin.x/y/z pool.game, mm) + centre (um / 1000); y is the centre's height R.
# Reads: @s pool.x pool.z; $origin.* pool.game. Writes: @s Pos; temporary #display.p pool.tmp.
scoreboard players operation #display.p pool.tmp = @s pool.x
scoreboard players operation #display.p pool.tmp /= #1000 pool.const
scoreboard players operation #display.p pool.tmp += $origin.x pool.game
execute store result entity @s Pos[0] double 0.001 run scoreboard players get #display.p pool.tmp
scoreboard players operation #display.p pool.tmp = @s pool.z
scoreboard players operation #display.p pool.tmp /= #1000 pool.const
scoreboard players operation #display.p pool.tmp += $origin.z pool.game
execute store result entity @s Pos[2] double 0.001 run scoreboard players get #display.p pool.tmp
scoreboard players operation #display.p pool.tmp = $R pool.const
scoreboard players operation #display.p pool.tmp /= #1000 pool.const
scoreboard players operation #display.p pool.tmp += $origin.y pool.game
execute store result entity @s Pos[1] double 0.001 run scoreboard players get #display.p pool.tmp
