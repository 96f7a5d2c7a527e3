execute as @e[type=marker,tag=ticker.new] run tag @s add ticker.seen
