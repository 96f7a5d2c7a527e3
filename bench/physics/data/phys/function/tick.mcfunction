# the step of every awake body, the statistics, the quicksort on ticks 1, 11, 21...
execute unless data storage phys:flags {running:1b} run return 0
scoreboard players add #tick phys.tmp 1
data modify storage phys:flags contact set value 0b
execute as @e[tag=phys.body,tag=!phys.sleep] at @s run function phys:body/step
execute store result storage phys:stats near int 1 if entity @e[tag=phys.near]
execute store result storage phys:stats tick int 1 run scoreboard players get #tick phys.tmp
scoreboard players operation #phase phys.tmp = #tick phys.tmp
scoreboard players operation #phase phys.tmp %= #sort_every phys.const
execute if score #phase phys.tmp matches 1 run function phys:sort/start
