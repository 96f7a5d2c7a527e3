"""Physical constants of a real 9-ft pool table (SI units), from seed/errata.md.

The datapack's load function states the same values in its fixed-point units.
"""
G = 9.81                      # m/s^2
BALL_RADIUS = 0.028575        # m
BALL_MASS = 0.170             # kg
BALL_INERTIA = 0.4 * BALL_MASS * BALL_RADIUS**2
MU_SLIDE = 0.2                # cloth sliding friction mu_s
MU_ROLL = 0.01                # rolling resistance: deceleration mu_r g (errata 1.2)
MU_SPIN = 0.0127              # side-spin friction: d(omega_y)/dt = -5 mu_sp g / (2R)
CUSHION_RESTITUTION = 0.85
CUSHION_FRICTION = 0.2
TABLE_LENGTH = 2.54           # playing area, m (x)
TABLE_WIDTH = 1.27            # m (z)
CUE_MASS = 0.567              # kg
CUE_LENGTH = 1.47             # m, a uniform rod: centre of mass l_s = L/2 behind the tip
CUE_INERTIA = CUE_MASS * CUE_LENGTH**2 / 12
CUE_TIP_TO_CENTRE = CUE_LENGTH / 2
TICKS_PER_SECOND = 20

# Pockets (a simplified model shared with the datapack): a ball whose centre reaches a rail's
# line (R inside the cushion) within a pocket opening drops; elsewhere it rebounds.
CORNER_OPENING = 0.09         # m along each rail from the corner
SIDE_OPENING_HALF = 0.065     # m either side of the middle of each long rail

SLIDE_DECELERATION = MU_SLIDE * G           # |dv/dt| while sliding
ROLL_DECELERATION = MU_ROLL * G             # |dv/dt| while rolling
SPIN_DECELERATION = 2.5 * MU_SPIN * G       # |d(wy)/dt|, wy = R omega_y
