scoreboard objectives add lib.data dummy
scoreboard players add #loads lib.data 1
