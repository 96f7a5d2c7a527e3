scoreboard objectives add crafting.heard dummy
