# pool:physics/motion/advance — move @s forward by #motion.step pool.tmp (1/10000 tick) under its
# current phase, crossing the end of sliding (the snap) or of rolling; side spin decays meanwhile.
# Reads: #motion.step pool.tmp; @s ball scores. Writes: @s ball scores; temporary #motion.f
# #slide.rest pool.tmp.
scoreboard players operation #motion.f pool.tmp = #motion.step pool.tmp
function pool:physics/motion/spin/advance
execute if score @s pool.state matches 1 run return run function pool:physics/motion/slide/advance_split
execute if score @s pool.state matches 2 run function pool:physics/motion/roll/advance
