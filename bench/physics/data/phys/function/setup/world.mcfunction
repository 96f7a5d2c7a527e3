# N bodies (a macro argument), the tick counter at 0, the ticks running
kill @e[tag=phys.body]
$scoreboard players set #bodies phys.const $(bodies)
scoreboard players set #i phys.tmp 0
scoreboard players set #tick phys.tmp 0
execute if score #bodies phys.const matches 1.. run function phys:setup/spawn
data modify storage phys:flags running set value 1b
