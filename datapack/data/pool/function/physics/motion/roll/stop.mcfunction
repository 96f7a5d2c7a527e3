# pool:physics/motion/roll/stop — @s comes to rest: no velocity, no rolling spin (side spin may
# remain).
# Writes: @s pool.state (0) pool.vx pool.vz pool.wx pool.wz pool.spd.
scoreboard players set @s pool.state 0
scoreboard players set @s pool.vx 0
scoreboard players set @s pool.vz 0
scoreboard players set @s pool.wx 0
scoreboard players set @s pool.wz 0
scoreboard players set @s pool.spd 0
