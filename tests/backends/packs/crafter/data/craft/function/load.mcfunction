scoreboard objectives add craft.rank dummy
scoreboard objectives add craft.found dummy
