# objectives, constants and flags; phys:setup/world {bodies:N} makes the bodies and starts the ticks
scoreboard objectives add phys.id dummy
scoreboard objectives add phys.x dummy
scoreboard objectives add phys.y dummy
scoreboard objectives add phys.z dummy
scoreboard objectives add phys.yaw dummy
scoreboard objectives add phys.energy dummy
scoreboard objectives add phys.hits dummy
scoreboard objectives add phys.size dummy
scoreboard objectives add phys.age dummy
scoreboard objectives add phys.key dummy
scoreboard objectives add phys.seg dummy
scoreboard objectives add phys.base dummy
scoreboard objectives add phys.rank dummy
scoreboard objectives add phys.tmp dummy
scoreboard objectives add phys.const dummy
scoreboard players set #sort_every phys.const 10
scoreboard players set #2 phys.const 2
scoreboard players set #3 phys.const 3
scoreboard players set #4 phys.const 4
scoreboard players set #8 phys.const 8
scoreboard players set #16 phys.const 16
scoreboard players set #37 phys.const 37
scoreboard players set #360 phys.const 360
scoreboard players set #1000 phys.const 1000
scoreboard players set #1500 phys.const 1500
scoreboard players set #tick phys.tmp 0
data modify storage phys:flags running set value 0b
data modify storage phys:flags sorting set value 0b
data modify storage phys:flags contact set value 0b
