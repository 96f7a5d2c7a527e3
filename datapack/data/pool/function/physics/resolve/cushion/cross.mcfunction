# pool:physics/resolve/cushion/cross — move @s, rewound to the chord's crossing time #events.te, to
# where its own path crosses the rail line: the time of the crossing solves p + vo dt + ao dt^2 / 2 =
# 0 (p past the line, vo the outward speed, ao the outward acceleration of a sliding ball) by one
# Newton step from dt = -p / vo (pool:physics/resolve/cushion/newton); the ball is rewound to te + dt (pool:physics/events/rewind, within
# #events.now..10000; the event then happens at that time), and what is left below the time step
# (1e-4 tick: up to 50 um at 10 m/s) is moved along its velocity, r -= v p / vo. A ball that does not
# move out, or a crossing more than half a tick away, is only put on the line
# (pool:physics/resolve/cushion).
# Reads: #cushion.nx #cushion.nz #cushion.off #events.te #events.now pool.tmp, @s scores. Writes: @s
# position (and state when rewound), #events.te; #cushion.p #cushion.vo #cushion.dt #cushion.q
# #cushion.d pool.tmp and the math library's temporaries.
function pool:physics/resolve/cushion/past
execute if score #cushion.vo pool.tmp matches ..0 run return 0
execute unless score #cushion.p pool.tmp matches -100000..100000 run return 0
scoreboard players operation $a pool.math = #cushion.p pool.tmp
scoreboard players operation $a pool.math *= #-1 pool.const
scoreboard players operation $b pool.math = #cushion.vo pool.tmp
function pool:math/div_1e4
scoreboard players operation #cushion.dt pool.tmp = $out pool.math
execute unless score #cushion.dt pool.tmp matches -5000..5000 run return 0
execute if score @s pool.state matches 1 run function pool:physics/resolve/cushion/newton
scoreboard players operation #cushion.q pool.tmp = #events.te pool.tmp
scoreboard players operation #events.te pool.tmp += #cushion.dt pool.tmp
scoreboard players operation #events.te pool.tmp > #events.now pool.tmp
execute if score #events.te pool.tmp matches 10001.. run scoreboard players set #events.te pool.tmp 10000
execute unless score #events.te pool.tmp = #cushion.q pool.tmp run function pool:physics/events/rewind
function pool:physics/resolve/cushion/past
execute if score #cushion.vo pool.tmp matches ..0 run return 0
execute unless score #cushion.p pool.tmp matches -2000..2000 run return 0
scoreboard players operation $b pool.math = #cushion.vo pool.tmp
scoreboard players operation $a pool.math = @s pool.vx
scoreboard players operation $a pool.math *= #cushion.p pool.tmp
function pool:math/div_round
scoreboard players operation @s pool.x -= $out pool.math
scoreboard players operation $a pool.math = @s pool.vz
scoreboard players operation $a pool.math *= #cushion.p pool.tmp
function pool:math/div_round
scoreboard players operation @s pool.z -= $out pool.math
