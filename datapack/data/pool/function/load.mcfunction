# pool:load — create every objective and constant. Runs from #minecraft:load.
# Reads: nothing. Writes: all objectives below, constants on pool.const.
#
# Fixed-point units (20 ticks per second):
#   length          micrometres (um); table frame: origin at a corner of the playing
#                   area, x along the long side (0..2540000), z along the short side (0..1270000)
#   velocity        um/tick (10 m/s = 500000)
#   spin            w = R (omega x up): velocity of the ball surface at the cloth in um/tick,
#                   so the slip is u = v - w and the ball rolls when w = v;
#                   side spin wy = R omega_y in um/tick (positive = counter-clockwise from above)
#   unit vectors    x 10000 (a rolling ball's direction x 100000)
#   rolling speed   0.01 um/tick; rolling distance 0.01 um
#   time in a tick  1/10000 tick
#   sliding         acceleration 0.001 um/tick^2; its fine state in 1/2000 um and um/tick
#   angles          1/100 degree (centidegrees)
# Ball states (pool.state): 0 at rest, 1 sliding, 2 rolling, 3 pocketed.

# Per-ball state (on @e[tag=pool.ball])
scoreboard objectives add pool.id dummy
scoreboard objectives add pool.state dummy
scoreboard objectives add pool.x dummy
scoreboard objectives add pool.z dummy
scoreboard objectives add pool.vx dummy
scoreboard objectives add pool.vz dummy
scoreboard objectives add pool.wx dummy
scoreboard objectives add pool.wz dummy
scoreboard objectives add pool.wy dummy
# sliding phase: acceleration (0.001 um/tick^2), remaining slide time (1/10000 tick), rolling
# velocity at its end (um/tick); the fine state the slide runs on: the position's part below a um
# (1/2000 um), velocity and spin (1/2000 um/tick)
scoreboard objectives add pool.ax dummy
scoreboard objectives add pool.az dummy
scoreboard objectives add pool.tau dummy
scoreboard objectives add pool.rx dummy
scoreboard objectives add pool.rz dummy
scoreboard objectives add pool.px dummy
scoreboard objectives add pool.pz dummy
scoreboard objectives add pool.fvx dummy
scoreboard objectives add pool.fvz dummy
scoreboard objectives add pool.fwx dummy
scoreboard objectives add pool.fwz dummy
# rolling phase: start position (um), direction (x 100000), speed (0.01 um/tick), distance (0.01 um)
scoreboard objectives add pool.x0 dummy
scoreboard objectives add pool.z0 dummy
scoreboard objectives add pool.dx dummy
scoreboard objectives add pool.dz dummy
scoreboard objectives add pool.spd dummy
scoreboard objectives add pool.s dummy
# state saved at the tick's start or at the ball's last event (time pool.bt), restored to rewind
scoreboard objectives add pool.bx dummy
scoreboard objectives add pool.bz dummy
scoreboard objectives add pool.bvx dummy
scoreboard objectives add pool.bvz dummy
scoreboard objectives add pool.bwx dummy
scoreboard objectives add pool.bwz dummy
scoreboard objectives add pool.bwy dummy
scoreboard objectives add pool.btau dummy
scoreboard objectives add pool.bs dummy
scoreboard objectives add pool.bspd dummy
scoreboard objectives add pool.bstate dummy
scoreboard objectives add pool.bt dummy
scoreboard objectives add pool.bpx dummy
scoreboard objectives add pool.bpz dummy
scoreboard objectives add pool.bfvx dummy
scoreboard objectives add pool.bfvz dummy
scoreboard objectives add pool.bfwx dummy
scoreboard objectives add pool.bfwz dummy
# the ball's chord in this tick: from (cx, cz) at time ct (1/10000 tick) to (x, z) at the tick's end
scoreboard objectives add pool.cx dummy
scoreboard objectives add pool.cz dummy
scoreboard objectives add pool.ct dummy
# the earliest event found for a ball as the first of a pair: absolute time in the tick
# (1/10000 tick, 20000 = none), kind (1 ball, 2 cushion, 3 pocket), rail (read with kinds 2 and 3),
# partner's pool.id (read with kind 1)
scoreboard objectives add pool.nt dummy
scoreboard objectives add pool.nk dummy
scoreboard objectives add pool.nr dummy
scoreboard objectives add pool.np dummy
# the box around a ball's chord in this tick, grown by R (um)
scoreboard objectives add pool.lx dummy
scoreboard objectives add pool.hx dummy
scoreboard objectives add pool.lz dummy
scoreboard objectives add pool.hz dummy

# Temporaries, math library I/O, constants, game state
scoreboard objectives add pool.tmp dummy
scoreboard objectives add pool.math dummy
scoreboard objectives add pool.const dummy
scoreboard objectives add pool.game dummy
scoreboard objectives add pool.power trigger

# Constants named by value
scoreboard players set #-1 pool.const -1
scoreboard players set #2 pool.const 2
scoreboard players set #4 pool.const 4
scoreboard players set #5 pool.const 5
scoreboard players set #7 pool.const 7
scoreboard players set #10 pool.const 10
scoreboard players set #100 pool.const 100
scoreboard players set #256 pool.const 256
scoreboard players set #1000 pool.const 1000
scoreboard players set #2000 pool.const 2000
scoreboard players set #10000 pool.const 10000
scoreboard players set #20000 pool.const 20000
scoreboard players set #16384 pool.const 16384
scoreboard players set #32767 pool.const 32767
scoreboard players set #32768 pool.const 32768
scoreboard players set #100000 pool.const 100000
scoreboard players set #100000000 pool.const 100000000

# Physical constants (see emulator/physics/constants.py for the same values in SI)
# ball radius R = 28.575 mm; 2R = 57150 um
scoreboard players set $R pool.const 28575
scoreboard players set $2R pool.const 57150
# centre distance at which the swept test reports a contact: 2R + 20 um (see
# pool:physics/detect/sweep/pair)
scoreboard players set $contact pool.const 57170
# the overlap at which a touching pair that did not approach becomes a contact when the two run into
# each other later in the tick (see pool:physics/detect/pair/recontact), um
scoreboard players set $recontact pool.const 50
# playing area 2.54 m x 1.27 m
scoreboard players set $L pool.const 2540000
scoreboard players set $W pool.const 1270000
# pocket openings along the rail lines: 90 mm from each corner, 65 mm either side of a long rail's middle
scoreboard players set $corner_open pool.const 90000
scoreboard players set $side_open pool.const 65000
# sliding friction mu_s g = 0.2 * 9.81 m/s^2 = 4905 um/tick^2
scoreboard players set $mu_s_g pool.const 4905
# rolling resistance mu_r g = 0.01 * 9.81 m/s^2 = 24525 (0.01 um/tick^2)
scoreboard players set $mu_r_g pool.const 24525
# a whole tick of rolling (pool:physics/motion/roll/whole_tick): the distance lost, mu_r g / 2
# rounded as pool:math/div_round rounds it, and the speed 2 mu_r g from which the ball cannot stop
# within it
scoreboard players operation $mu_r_g_half pool.const = $mu_r_g pool.const
scoreboard players add $mu_r_g_half pool.const 1
scoreboard players operation $mu_r_g_half pool.const /= #2 pool.const
scoreboard players operation $roll_tick_min pool.const = $mu_r_g pool.const
scoreboard players operation $roll_tick_min pool.const *= #2 pool.const
# side-spin decay (5/2) mu_sp g = 2.5 * 0.0127 * 9.81 m/s^2 = 778.67 um/tick^2, rounded to 779
scoreboard players set $spin_decay pool.const 779
# cushion restitution e = 0.85 and friction mu_c = 0.2, both x 10000
scoreboard players set $e_cushion pool.const 8500
scoreboard players set $mu_cushion pool.const 2000

# commands a game tick may spend on the table's physics, as pool:physics/step estimates them
# (#cost.work): the issue's budget is 5000 per tick, and a step admitted last may pass the
# estimate by a few hundred; the rest of a physics tick carries over
scoreboard players set $budget pool.const 4300
# pool:physics/detect/sweep/unit remembers its last result: forget it, the reloaded math may differ
scoreboard players reset #sweep.unit.x pool.tmp

# Game state (public): $resting pool.game is 1 when no ball moves; $pocketed counts pocketed balls
# and $last_pocketed holds the number of the last one; the table corner $origin.x/y/z is in mm;
# $carry pool.game is 1 while a physics tick is carried over to the next game tick (the balls'
# scores are then mid-computation; the displays show the last complete tick).
execute unless score $resting pool.game matches 0..1 run scoreboard players set $resting pool.game 1
