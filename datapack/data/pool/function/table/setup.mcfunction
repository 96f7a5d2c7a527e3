# pool:table/setup — set up a table at the executor's position (the corner of the playing area;
# the long side runs east, +x, the short side south, +z) and rack the balls.
# Writes: $origin.x/y/z pool.game (mm), the ball entities (via pool:table/rack), $resting, $pocketed.
summon marker ~ ~ ~ {Tags:["pool.origin"]}
execute as @e[type=marker,tag=pool.origin,limit=1] run function pool:table/read_origin
kill @e[type=marker,tag=pool.origin]
function pool:table/rack
