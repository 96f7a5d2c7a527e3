# pool:physics/resolve/pocket — @s drops into a pocket: it leaves play and is reported.
# Writes: @s pool.state (3), motion scores and tag pool.moving; $pocketed $last_pocketed pool.game;
# its display goes to the ball return (pool:physics/display/tray).
function pool:physics/motion/roll/stop
tag @s remove pool.moving
scoreboard players set @s pool.state 3
scoreboard players set @s pool.wy 0
scoreboard players add $pocketed pool.game 1
scoreboard players operation $last_pocketed pool.game = @s pool.id
tellraw @a [{"text":"Pool: ball "},{"score":{"name":"@s","objective":"pool.id"}},{"text":" is pocketed"}]
function pool:physics/display/tray
