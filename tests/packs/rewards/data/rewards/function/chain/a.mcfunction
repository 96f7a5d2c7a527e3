scoreboard players add @s rewards.chain 1
advancement grant @s only rewards:chain_b
