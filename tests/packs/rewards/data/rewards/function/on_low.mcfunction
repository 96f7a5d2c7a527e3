scoreboard players add @s rewards.low 1
advancement revoke @s only rewards:low
