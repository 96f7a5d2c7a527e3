# @batch cue_strike
# Cue strike (pool:cue/strike through pool:api/shot, errata 5.x): the tip offset gives spin
# (above centre: follow, to the side: side spin), a raised cue bends the spin axis (masse).
# Expected values from the float reference (emulator/physics): strike(Shot(angle, speed, tip_x,
# tip_y, elevation)) in um/tick. Tolerances (DESIGN.md section 6): ball speed 0.1 %, spin 0.5 %
# of its size, per component, plus 1 um/tick.
function pool:table/setup
kill @e[tag=pool.ball]
# 30 degrees, 2 m/s, tip 0.3 R above centre: v = (113590.2, 65581.4), w = (85192.7, 49186.0), wy = 0
function pool:table/rack/ball {id:0, x:635000, z:635000, item:"minecraft:white_concrete"}
function pool:api/shot {angle:3000, speed:2000, tip_x:0, tip_y:300, elevation:0}
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vx matches 113458..113722
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vz matches 65449..65714
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.wx matches 84700..85685
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.wz matches 48693..49679
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.wy matches -1..1

# 0 degrees, 3 m/s, tip 0.2 R left: v = (214312.7, 0), w = 0, wy = -107156.4
kill @e[tag=pool.ball]
scoreboard players set $resting pool.game 1
function pool:table/rack/ball {id:0, x:635000, z:635000, item:"minecraft:white_concrete"}
function pool:api/shot {angle:0, speed:3000, tip_x:-200, tip_y:0, elevation:0}
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vx matches 214098..214527
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vz matches -1..1
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.wx matches -1..1
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.wy matches -107693..-106620

# 90 degrees, 2.5 m/s, tip 0.3 R right, cue raised 20 degrees: v = (0, 154065.8),
# w = (-42056.5, 0), wy = 115549.3 (spin size 122965: 0.5 % is 615)
kill @e[tag=pool.ball]
scoreboard players set $resting pool.game 1
function pool:table/rack/ball {id:0, x:635000, z:635000, item:"minecraft:white_concrete"}
function pool:api/shot {angle:9000, speed:2500, tip_x:300, tip_y:0, elevation:2000}
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vx matches -155..155
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vz matches 153911..154221
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.wx matches -42672..-41441
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.wz matches -616..616
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.wy matches 114933..116165

# 0 degrees, 6.5 m/s, cue raised 89 degrees: v = (8727.4, 0); cos 89 degrees = 0.0174524 must
# keep 5 digits (0.0175 would make the ball 0.27 % fast)
kill @e[tag=pool.ball]
scoreboard players set $resting pool.game 1
function pool:table/rack/ball {id:0, x:635000, z:635000, item:"minecraft:white_concrete"}
function pool:api/shot {angle:0, speed:6500, tip_x:0, tip_y:0, elevation:8900}
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vx matches 8719..8736
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vz matches 0

# 30 degrees, 2 m/s, a tiny tip offset 0.003 R right, 0.002 R below: w = (-666.2, -384.7),
# wy = 1154.0, each within 0.5 % (the spin factors must not be rounded to 1e-4 before the product)
kill @e[tag=pool.ball]
scoreboard players set $resting pool.game 1
function pool:table/rack/ball {id:0, x:635000, z:635000, item:"minecraft:white_concrete"}
function pool:api/shot {angle:3000, speed:2000, tip_x:3, tip_y:-2, elevation:0}
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.wx matches -669..-663
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.wz matches -386..-383
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.wy matches 1149..1159
