# pool:api/shot/refuse — tell every player why a shot is refused (macro argument: reason).
# Writes: #ok pool.tmp (0).
$tellraw @a {"text":"Pool: shot refused: $(reason)","color":"red"}
scoreboard players set #ok pool.tmp 0
