# one partition: the first body still to sort is the pivot of its segment; the segment's others
# go to two new segments, below and above it; the pivot's rank is its base plus those below
execute as @e[tag=phys.sort,limit=1] run function phys:sort/pivot
scoreboard players operation #lo phys.seg = #next phys.seg
scoreboard players add #next phys.seg 1
scoreboard players operation #hi phys.seg = #next phys.seg
scoreboard players add #next phys.seg 1
scoreboard players set #below phys.tmp 0
execute as @e[tag=phys.sort,tag=!phys.pivot] if score @s phys.seg = #cur phys.seg run function phys:sort/part
scoreboard players operation #hibase phys.tmp = #base phys.tmp
scoreboard players operation #hibase phys.tmp += #below phys.tmp
scoreboard players add #hibase phys.tmp 1
execute as @e[tag=phys.sort] if score @s phys.seg = #hi phys.seg run scoreboard players operation @s phys.base = #hibase phys.tmp
execute as @e[tag=phys.pivot] run function phys:sort/place
execute if entity @e[tag=phys.sort] run function phys:sort/step
