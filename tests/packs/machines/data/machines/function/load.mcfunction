scoreboard objectives add machines.read dummy
