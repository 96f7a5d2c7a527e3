# @batch api_shot_refused
# @dummy
# pool:api/shot refuses a shot out of range, or with no cue ball on the table (none is set up
# here): it tells the players (the dummy receives the chat) every reason and stores nothing.
scoreboard players set $shot.speed pool.game -1
function pool:api/shot {angle:0, speed:9000, tip_x:0, tip_y:0, elevation:0}
assert chat "^Pool: shot refused: speed must be 1\\.\\.6500 \\(mm/s\\)$"
assert chat "^Pool: shot refused: the cue ball is not on the table"
assert not chat "tip_x must be"
assert score $shot.speed pool.game matches -1
assert score $resting pool.game matches 1
