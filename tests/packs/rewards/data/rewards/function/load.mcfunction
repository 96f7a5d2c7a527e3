scoreboard objectives add rewards.ticks dummy
scoreboard objectives add rewards.chain dummy
scoreboard objectives add rewards.low dummy
scoreboard objectives add rewards.got dummy
