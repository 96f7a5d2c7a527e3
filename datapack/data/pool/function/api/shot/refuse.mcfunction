# pool:api/shot/refuse — tell every player why a shot is refused (macro argument: reason).
# Writes: #api.ok pool.tmp (0).
$tellraw @a {"text":"Pool: shot refused: $(reason)","color":"red"}
scoreboard players set #api.ok pool.tmp 0
