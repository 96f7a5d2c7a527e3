# a predicate-gated tick: only marked undead count their ticks
execute as @e[predicate=gated:marked_undead] run scoreboard players add @s gated.ticks 1
