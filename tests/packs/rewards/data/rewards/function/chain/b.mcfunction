scoreboard players add @s rewards.chain 10
