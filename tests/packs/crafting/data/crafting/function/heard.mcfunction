scoreboard players add @s crafting.heard 1
