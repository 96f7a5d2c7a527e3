scoreboard objectives add probe dummy
scoreboard players add #loads probe 1
