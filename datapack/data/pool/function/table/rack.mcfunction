# pool:table/rack — remove every ball and place a fresh rack: the cue ball (0) on the head spot
# (L/4, W/2) and 15 balls in a triangle from the foot spot (3L/4, W/2), 30 um apart
# (rows 49519 um apart = (2R + 30) cos 30 degrees, balls 57180 um apart in a row).
# Writes: the ball entities and their scores; $resting (1), $pocketed (0) pool.game.
kill @e[tag=pool.ball]
# a physics tick left unfinished by the old balls is dropped with them
scoreboard players set $carry pool.game 0
function pool:table/rack/ball {id:0,x:635000,z:635000,item:"minecraft:white_concrete"}
function pool:table/rack/ball {id:1,x:1905000,z:635000,item:"minecraft:yellow_concrete"}
function pool:table/rack/ball {id:9,x:1954519,z:606410,item:"minecraft:yellow_terracotta"}
function pool:table/rack/ball {id:2,x:1954519,z:663590,item:"minecraft:blue_concrete"}
function pool:table/rack/ball {id:10,x:2004038,z:577820,item:"minecraft:blue_terracotta"}
function pool:table/rack/ball {id:8,x:2004038,z:635000,item:"minecraft:black_concrete"}
function pool:table/rack/ball {id:3,x:2004038,z:692180,item:"minecraft:red_concrete"}
function pool:table/rack/ball {id:4,x:2053557,z:549230,item:"minecraft:purple_concrete"}
function pool:table/rack/ball {id:11,x:2053557,z:606410,item:"minecraft:red_terracotta"}
function pool:table/rack/ball {id:5,x:2053557,z:663590,item:"minecraft:orange_concrete"}
function pool:table/rack/ball {id:12,x:2053557,z:720770,item:"minecraft:purple_terracotta"}
function pool:table/rack/ball {id:13,x:2103076,z:520640,item:"minecraft:orange_terracotta"}
function pool:table/rack/ball {id:6,x:2103076,z:577820,item:"minecraft:green_concrete"}
function pool:table/rack/ball {id:14,x:2103076,z:635000,item:"minecraft:green_terracotta"}
function pool:table/rack/ball {id:7,x:2103076,z:692180,item:"minecraft:brown_concrete"}
function pool:table/rack/ball {id:15,x:2103076,z:749360,item:"minecraft:brown_terracotta"}
scoreboard players set $resting pool.game 1
scoreboard players set $pocketed pool.game 0
