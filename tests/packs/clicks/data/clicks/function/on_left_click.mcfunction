# the reward runs as the player: find the buttons whose last attacker it is
tag @s add clicks.source
execute as @e[type=interaction,tag=clicks.button,distance=..8] on attacker if entity @s[tag=clicks.source] run scoreboard players add @s clicks.left 1
execute as @e[type=interaction,tag=clicks.button,distance=..8] if function clicks:attacked_by_source run tag @s add clicks.hit
tag @s remove clicks.source
advancement revoke @s only clicks:left_click
