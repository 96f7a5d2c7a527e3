scoreboard objectives add healing.heals dummy
scoreboard objectives add healing.given dummy
