# @batch controls_full_power
# @timeout 10
# @dummy
# The player controls (pool:controls/*): a view with yaw 0 faces south, the table's +z; a trigger
# value over 100 is full power (6.5 m/s).
# Expected from the float reference (emulator/physics): strike(Shot(90 degrees, 6.5)) gives
# 500067.8 um/tick along +z, then one tick of sliding takes off mu_s g = 4905 um/tick: 495162.8
# (tolerance: the strike's 0.1 %, 500 um/tick, plus 2).
function pool:table/setup
kill @e[tag=pool.ball]
function pool:table/rack/ball {id:0, x:635000, z:300000, item:"minecraft:white_concrete"}
tp @s ~ ~ ~ 0 0
await delay 1
trigger pool.power set 150
await score @s pool.power matches 0
assert score $shot.speed pool.game matches 6500
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vz matches 494661..495665
assert score @e[tag=pool.ball,scores={pool.id=0},limit=1] pool.vx matches -2..2
