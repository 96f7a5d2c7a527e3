# @batch physics_resolve_cushion
# @timeout 20
# Cushion rebound (pool:physics/resolve/cushion/rebound, errata 4.x: Coulomb friction with a stick
# limit): the normal speed comes back times e = 0.85, friction trims the speed along the rail and
# turns it into side spin; through the tick loop, a ball rolling into the foot rail comes back.
# Expected values from the float reference (emulator/physics): cushion.rebound(v = (-150000, 60000)
# um/tick, wy = 4000, n = (1, 0)) gives v = (127500, 41714.3), wy = -41714.3; tolerance 2 um/tick
# (DESIGN.md section 6: normal-speed ratio 1e-3, angle 0.25 degree). strike(Shot(0, 1.0, 0, 0.4))
# rolls at 58829.6 um/tick; simulate_ticks from x = 2300000 um: it meets the rail in tick 4 and
# after it moves at vx = -47392.2, after tick 5 at -42487.2 um/tick from x = 2448180 um.
# Tolerances: the strike's 0.1 % (59 um/tick) and the rebound's 1e-3 plus 2, rounded up to 120
# um/tick; position 1 mm + 0.1 % of the path.
function pool:table/setup
kill @e[tag=pool.ball]
function pool:table/rack/ball {id:0, x:100000, z:635000, item:"minecraft:white_concrete"}
scoreboard players set @e[tag=pool.ball,scores={pool.id=0}] pool.vx -150000
scoreboard players set @e[tag=pool.ball,scores={pool.id=0}] pool.vz 60000
scoreboard players set @e[tag=pool.ball,scores={pool.id=0}] pool.wy 4000
scoreboard players set #cushion.nx pool.tmp 1
scoreboard players set #cushion.nz pool.tmp 0
execute as @e[tag=pool.ball,scores={pool.id=0}] run function pool:physics/resolve/cushion/rebound
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vx matches 127498..127502
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vz matches 41712..41716
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.wy matches -41716..-41712

# through the tick loop: rolling into the foot rail (x = L)
kill @e[tag=pool.ball]
function pool:table/rack/ball {id:0, x:2300000, z:635000, item:"minecraft:white_concrete"}
function pool:api/shot {angle:0, speed:1000, tip_x:0, tip_y:400, elevation:0}
await delay 3
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vx matches 1..
await delay 1
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vx matches -47512..-47272
await delay 1
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vx matches -42607..-42367
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.x matches 2446830..2449530
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.z matches 635000
