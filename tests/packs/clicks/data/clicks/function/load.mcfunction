scoreboard objectives add clicks.left dummy
scoreboard objectives add clicks.n dummy
