"""Physical constants of a real 9-ft pool table (SI units), from seed/errata.md.

The datapack's load function states the same values in its fixed-point units.
"""
from dataclasses import dataclass

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
CUE_TIP_TO_CENTRE = CUE_LENGTH / 2
TICKS_PER_SECOND = 20

# Pockets (a simplified model shared with the datapack): a ball whose centre reaches a rail's
# line (R inside the cushion) within a pocket opening drops; elsewhere it rebounds.
CORNER_OPENING = 0.09         # m along each rail from the corner
SIDE_OPENING_HALF = 0.065     # m either side of the middle of each long rail

SLIDE_DECELERATION = MU_SLIDE * G           # |dv/dt| while sliding
ROLL_DECELERATION = MU_ROLL * G             # |dv/dt| while rolling
SPIN_DECELERATION = 2.5 * MU_SPIN * G       # |d(wy)/dt|, wy = R omega_y


@dataclass(frozen=True)
class Constants:
    """The constants a simulation runs with: :data:`EXACT` holds the seed's values above;
    :func:`poolgame.physics.pack.pack_constants` reads a pack's integer constants back into SI
    (the difference between the two is what quantising the constants alone costs)."""

    slide_deceleration: float = SLIDE_DECELERATION   # m/s^2
    roll_deceleration: float = ROLL_DECELERATION     # m/s^2
    spin_deceleration: float = SPIN_DECELERATION     # m/s^2 (of wy = R omega_y)
    cushion_restitution: float = CUSHION_RESTITUTION
    cushion_friction: float = CUSHION_FRICTION
    mass_ratio: float = BALL_MASS / CUE_MASS          # m_b / m_s


EXACT = Constants()
