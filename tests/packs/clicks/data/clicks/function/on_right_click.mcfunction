tag @s add clicks.source
execute as @e[type=interaction,tag=clicks.button,distance=..8] if function clicks:used_by_source run tag @s add clicks.used
execute as @e[type=interaction,tag=clicks.used,distance=..8] run data remove entity @s interaction
tag @s remove clicks.source
advancement revoke @s only clicks:right_click
