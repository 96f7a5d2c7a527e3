scoreboard objectives add squads.n dummy
team add squads.red "Red"
team modify squads.red color red
team modify squads.red friendlyFire false
team modify squads.red prefix "[R] "
team add squads.blue
