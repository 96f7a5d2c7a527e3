scoreboard players add #ticks lib.data 1
