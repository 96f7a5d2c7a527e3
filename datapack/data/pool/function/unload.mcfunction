# pool:unload — remove what the pack made, for a world that drops it: the balls' item_display
# entities (pool:table/setup's) and any table-corner marker, then every objective pool:load
# creates, with all their scores (the balls', the game state, the constants, the temporaries, the
# players' trigger). The pack keeps no storage and schedules no function, so nothing else remains.
# Run it, then disable the pack (/datapack disable); until then pool:tick runs against missing
# objectives (its commands fail and change nothing), and /reload (pool:load) sets the pack up again.
# Reads: nothing. Writes: kills @e[tag=pool.ball] and @e[tag=pool.origin]; removes every pool.*
# objective of pool:load.
kill @e[tag=pool.ball]
kill @e[tag=pool.origin]
scoreboard objectives remove pool.id
scoreboard objectives remove pool.state
scoreboard objectives remove pool.x
scoreboard objectives remove pool.z
scoreboard objectives remove pool.vx
scoreboard objectives remove pool.vz
scoreboard objectives remove pool.wx
scoreboard objectives remove pool.wz
scoreboard objectives remove pool.wy
scoreboard objectives remove pool.ax
scoreboard objectives remove pool.az
scoreboard objectives remove pool.tau
scoreboard objectives remove pool.rx
scoreboard objectives remove pool.rz
scoreboard objectives remove pool.px
scoreboard objectives remove pool.pz
scoreboard objectives remove pool.fvx
scoreboard objectives remove pool.fvz
scoreboard objectives remove pool.fwx
scoreboard objectives remove pool.fwz
scoreboard objectives remove pool.x0
scoreboard objectives remove pool.z0
scoreboard objectives remove pool.dx
scoreboard objectives remove pool.dz
scoreboard objectives remove pool.spd
scoreboard objectives remove pool.s
scoreboard objectives remove pool.bx
scoreboard objectives remove pool.bz
scoreboard objectives remove pool.bvx
scoreboard objectives remove pool.bvz
scoreboard objectives remove pool.bwx
scoreboard objectives remove pool.bwz
scoreboard objectives remove pool.bwy
scoreboard objectives remove pool.btau
scoreboard objectives remove pool.bs
scoreboard objectives remove pool.bspd
scoreboard objectives remove pool.bstate
scoreboard objectives remove pool.bt
scoreboard objectives remove pool.bpx
scoreboard objectives remove pool.bpz
scoreboard objectives remove pool.bfvx
scoreboard objectives remove pool.bfvz
scoreboard objectives remove pool.bfwx
scoreboard objectives remove pool.bfwz
scoreboard objectives remove pool.cx
scoreboard objectives remove pool.cz
scoreboard objectives remove pool.ct
scoreboard objectives remove pool.nt
scoreboard objectives remove pool.nk
scoreboard objectives remove pool.nr
scoreboard objectives remove pool.np
scoreboard objectives remove pool.lx
scoreboard objectives remove pool.hx
scoreboard objectives remove pool.lz
scoreboard objectives remove pool.hz
scoreboard objectives remove pool.tmp
scoreboard objectives remove pool.math
scoreboard objectives remove pool.const
scoreboard objectives remove pool.game
scoreboard objectives remove pool.power
