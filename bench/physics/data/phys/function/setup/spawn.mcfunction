# one body per call, #i counting up to #bodies
summon item_display 0 64 0 {Tags:["phys.new","phys.body"],teleport_duration:1}
execute as @e[tag=phys.new,limit=1] run function phys:setup/init
scoreboard players add #i phys.tmp 1
execute if score #i phys.tmp < #bodies phys.const run function phys:setup/spawn
