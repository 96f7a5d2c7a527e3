scoreboard objectives add ticker.n dummy
# a repeating block far from the tests ticks the modules' tag every game tick
setblock 29999 0 29999 repeating_command_block{auto:1b,Command:"function #ticker:command_block_tick"}
