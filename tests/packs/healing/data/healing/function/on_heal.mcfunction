scoreboard players add @s healing.heals 1
