kill @e[type=armor_stand,tag=toolstand]
summon armor_stand 0 250 0 {Tags: ["toolstand"], Invisible: 1b, Marker: 1b}
setblock 0 251 0 chest
setblock 0 252 0 stone
