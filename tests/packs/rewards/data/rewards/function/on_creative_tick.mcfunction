scoreboard players add @s rewards.ticks 1000
