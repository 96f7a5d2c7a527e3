scoreboard objectives add rewards.ticks dummy
scoreboard objectives add rewards.chain dummy
scoreboard objectives add rewards.low dummy
