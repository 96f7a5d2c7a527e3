# pool:physics/motion/slide/advance_split — slide @s for #motion.f pool.tmp; if sliding ends within
# it, slide to the exact end, snap v = w = the closed-form rolling velocity, and roll for the rest.
# Reads: #motion.f pool.tmp; @s pool.tau pool.rx pool.rz. Writes: @s ball scores; temporary
# #slide.rest.
execute if score #motion.f pool.tmp <= @s pool.tau run return run function pool:physics/motion/slide/advance
scoreboard players operation #slide.rest pool.tmp = #motion.f pool.tmp
scoreboard players operation #slide.rest pool.tmp -= @s pool.tau
scoreboard players operation #motion.f pool.tmp = @s pool.tau
function pool:physics/motion/slide/advance
scoreboard players operation @s pool.vx = @s pool.rx
scoreboard players operation @s pool.vz = @s pool.rz
scoreboard players operation @s pool.wx = @s pool.rx
scoreboard players operation @s pool.wz = @s pool.rz
function pool:physics/motion/roll/start
scoreboard players operation #motion.f pool.tmp = #slide.rest pool.tmp
execute if score @s pool.state matches 2 run function pool:physics/motion/roll/advance
