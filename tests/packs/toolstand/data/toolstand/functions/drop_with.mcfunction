# the stand holds the storage's item, then "mines" the probe block with it into the chest
data modify entity @e[type=armor_stand,tag=toolstand,limit=1] HandItems[0] set from storage toolstand: tool
execute as @e[type=armor_stand,tag=toolstand,limit=1] run loot replace block 0 251 0 container.0 mine 0 252 0 mainhand
