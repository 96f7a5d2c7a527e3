scoreboard players add @s healing.given 1
advancement revoke @s only healing:given_by_player
