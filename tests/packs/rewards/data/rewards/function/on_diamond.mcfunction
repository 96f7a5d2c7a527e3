scoreboard players add @s rewards.got 1
