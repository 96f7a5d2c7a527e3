scoreboard players add #ticks ticker.n 1
