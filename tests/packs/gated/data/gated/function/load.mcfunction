scoreboard objectives add gated.ticks dummy
scoreboard objectives add gated.hp dummy
