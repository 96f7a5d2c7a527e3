"""Side-spin decay (errata, missing from pool-models): d(omega_y)/dt = -sign(omega_y) 5 mu_sp g /(2R),
clamped at zero; with wy = R omega_y the rate is (5/2) mu_sp g."""
from __future__ import annotations

import math

from poolgame.physics.constants import SPIN_DECELERATION


def decay_side_spin(wy: float, t: float, deceleration: float = SPIN_DECELERATION) -> float:
    return math.copysign(max(abs(wy) - deceleration * t, 0.0), wy)
