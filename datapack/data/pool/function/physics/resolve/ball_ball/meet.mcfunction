# pool:physics/resolve/ball_ball/meet — the event happens when the balls touch, not where the swept
# chords met: the first Newton step of pool:physics/resolve/ball_ball/touch (dt = g / c on straight
# paths) moves the event time #events.te by dt and rewinds both balls there along their own paths
# (pool:physics/events/rewind), so that their velocities, spins and the rest of the tick belong to
# the time of the contact; pool:physics/resolve/ball_ball/touch then closes what is left (below the
# time step, and the paths' curve over dt).
# Without this, a near-tangent pair moved millimetres along its paths keeps the velocities of the
# earlier time (a sliding ball's differ by its deceleration) and runs ahead for the rest of the tick.
# The time stays within #events.now and the next stored event of any other ball, so that events
# keep their order. Nothing moves when the gap is unknown (more than 2 mm), the pair does not
# approach, dt is more than half a tick or a ball would move more than 30 mm.
# Reads: #events.te #events.now pool.tmp, @s and b's (tag pool.event_b) scores. Writes: #events.te,
# both balls' state (b's again in #ball_ball.b.*), #ball_ball.c #ball_ball.dt #ball_ball.cap
# #ball_ball.te0 pool.tmp; those of
# pool:physics/resolve/ball_ball/touch/gap and the math library's.
function pool:physics/resolve/ball_ball/touch/gap
execute if score #ball_ball.g pool.tmp matches 2001 run return 0
function pool:physics/resolve/ball_ball/touch/closing
execute if score #ball_ball.c pool.tmp matches ..0 run return 0
# dt = g 10000 / c in 1/10000 tick
scoreboard players operation $a pool.math = #ball_ball.g pool.tmp
scoreboard players operation $b pool.math = #ball_ball.c pool.tmp
function pool:math/div_1e4
execute unless score $out pool.math matches -5000..5000 run return 0
scoreboard players operation #ball_ball.dt pool.tmp = $out pool.math
# no ball moves more than 30 mm (pool:physics/resolve/ball_ball/touch/step's limit)
scoreboard players operation $b pool.math = #ball_ball.dt pool.tmp
scoreboard players operation $a pool.math = @s pool.vx
function pool:math/mul_unit
execute unless score $out pool.math matches -30000..30000 run return 0
scoreboard players operation $a pool.math = @s pool.vz
function pool:math/mul_unit
execute unless score $out pool.math matches -30000..30000 run return 0
scoreboard players operation $a pool.math = #ball_ball.b.vx pool.tmp
function pool:math/mul_unit
execute unless score $out pool.math matches -30000..30000 run return 0
scoreboard players operation $a pool.math = #ball_ball.b.vz pool.tmp
function pool:math/mul_unit
execute unless score $out pool.math matches -30000..30000 run return 0
# within #events.now .. the next stored event of any other ball (events stay in time order) and the
# tick's end
scoreboard players set #ball_ball.cap pool.tmp 10000
scoreboard players operation #ball_ball.cap pool.tmp < @e[tag=pool.moving,tag=!pool.event,tag=!pool.event_b] pool.nt
scoreboard players operation #ball_ball.te0 pool.tmp = #events.te pool.tmp
scoreboard players operation #events.te pool.tmp += #ball_ball.dt pool.tmp
scoreboard players operation #events.te pool.tmp > #events.now pool.tmp
scoreboard players operation #events.te pool.tmp < #ball_ball.cap pool.tmp
execute if score #events.te pool.tmp = #ball_ball.te0 pool.tmp run return 0
function pool:physics/events/rewind
execute as @e[tag=pool.event_b,limit=1] run function pool:physics/events/rewind
execute as @e[tag=pool.event_b,limit=1] run function pool:physics/resolve/ball_ball/load_b
