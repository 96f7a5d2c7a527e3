# pool:physics/detect/chord/new — start of a sub-step for @s. A dirty ball (just saved or resolved,
# at #events.now) starts a new chord here, is advanced by #events.rem to the tick's end and boxed; a
# clean one keeps its chord and box (pool:physics/detect/chord/start moves the chord's start to
# #events.now when a sweep needs it).
# Reads: #events.now #events.rem pool.tmp, @s scores. Writes: tags pool.moving pool.dirty pool.fresh
# (a new chord), @s chord and state.
execute if entity @s[tag=!pool.dirty] run return 0
tag @s remove pool.dirty
tag @s add pool.fresh
tag @s remove pool.moving
execute if score @s pool.state matches 1..2 run tag @s add pool.moving
scoreboard players operation @s pool.cx = @s pool.x
scoreboard players operation @s pool.cz = @s pool.z
scoreboard players operation @s pool.ct = #events.now pool.tmp
scoreboard players operation #motion.step pool.tmp = #events.rem pool.tmp
function pool:physics/motion/advance
function pool:physics/detect/chord/box
