execute store result score @s craft.found run clear @s #craft:swords 0
