# pool:table/rack — remove every ball and place a fresh rack: the cue ball (0) on the head spot
# (L/4, W/2) and 15 balls in a triangle from the foot spot (3L/4, W/2), 2 um apart
# (rows 49495 um apart = (2R + 2) cos 30 degrees, balls 57152 um apart in a row).
# Writes: the ball entities and their scores; $resting (1), $pocketed (0) pool.game.
kill @e[tag=pool.ball]
function pool:table/rack/ball {id:0,x:635000,z:635000,item:"minecraft:white_concrete"}
function pool:table/rack/ball {id:1,x:1905000,z:635000,item:"minecraft:yellow_concrete"}
function pool:table/rack/ball {id:9,x:1954495,z:606424,item:"minecraft:yellow_terracotta"}
function pool:table/rack/ball {id:2,x:1954495,z:663576,item:"minecraft:blue_concrete"}
function pool:table/rack/ball {id:10,x:2003990,z:577848,item:"minecraft:blue_terracotta"}
function pool:table/rack/ball {id:8,x:2003990,z:635000,item:"minecraft:black_concrete"}
function pool:table/rack/ball {id:3,x:2003990,z:692152,item:"minecraft:red_concrete"}
function pool:table/rack/ball {id:4,x:2053485,z:549272,item:"minecraft:purple_concrete"}
function pool:table/rack/ball {id:11,x:2053485,z:606424,item:"minecraft:red_terracotta"}
function pool:table/rack/ball {id:5,x:2053485,z:663576,item:"minecraft:orange_concrete"}
function pool:table/rack/ball {id:12,x:2053485,z:720728,item:"minecraft:purple_terracotta"}
function pool:table/rack/ball {id:13,x:2102980,z:520696,item:"minecraft:orange_terracotta"}
function pool:table/rack/ball {id:6,x:2102980,z:577848,item:"minecraft:green_concrete"}
function pool:table/rack/ball {id:14,x:2102980,z:635000,item:"minecraft:green_terracotta"}
function pool:table/rack/ball {id:7,x:2102980,z:692152,item:"minecraft:brown_concrete"}
function pool:table/rack/ball {id:15,x:2102980,z:749304,item:"minecraft:brown_terracotta"}
scoreboard players set $resting pool.game 1
scoreboard players set $pocketed pool.game 0
