# pool:physics/finish — the end of a complete physics tick, when its estimated cost (about 150
# commands per ball that touched another, 300 for the displays) still fits in this game tick's
# $budget, else it carries over: balls that touched another are pushed apart, the displays follow
# the balls that moved, and the table may come to rest.
# Reads: #work pool.tmp, tags pool.touch pool.moving. Writes: #c pool.tmp, $carry pool.game, tags
# pool.found pool.fresh (removed), through
# pool:physics/separate/ball, pool:ball/display/place and pool:physics/at_rest.
execute store result score #c pool.tmp if entity @e[tag=pool.touch,scores={pool.state=0..2}]
scoreboard players set #k pool.tmp 150
scoreboard players operation #c pool.tmp *= #k pool.tmp
scoreboard players add #c pool.tmp 300
scoreboard players operation #c pool.tmp += #work pool.tmp
# (a game tick that has done nothing else yet finishes whatever the estimate, so that it gets on)
execute if score #work pool.tmp matches 1.. if score #c pool.tmp > $budget pool.const run return run scoreboard players set $carry pool.game 1
tag @e[tag=pool.found] remove pool.found
tag @e[tag=pool.fresh] remove pool.fresh
# a pair left touching but not approaching (pool:physics/find/touching) can end closer than 2R
# along converging chords, and the contact shift of pool:physics/resolve/touch can carry a ball a
# few um into a third one
execute as @e[tag=pool.touch,scores={pool.state=0..2}] run function pool:physics/separate/ball
tag @e[tag=pool.touch] remove pool.touch
execute as @e[tag=pool.moving] run function pool:ball/display/place
execute unless entity @e[tag=pool.ball,scores={pool.state=1..2}] run function pool:physics/at_rest
