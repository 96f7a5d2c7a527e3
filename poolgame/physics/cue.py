"""Cue strike (pool-models 5.1-5.7, errata 5.x): a rigid cue of mass m_s (centre of mass l_s
behind the tip) hits the ball elastically; the tip's friction impulse is mu J.

With n the unit normal from the contact point to the ball centre, theta the angle between the
cue direction d and n, and t = (d - cos(theta) n)/sin(theta):
  J = v_s0 (cos + mu sin) / [(1+mu^2)/(2 m_s) + (1+mu^2)/(2 m_b) + l_s^2 (mu cos - sin)^2/(2 I_s)
                             + R^2 mu^2 / (2 I_b)]                                      (5.5)
  v_b = (J/m_b)(n + mu t),  omega_b = (R mu J / I_b)(t x n).
The default friction mu = tan(theta) (the tip does not slip, the impulse lies along the cue)
reduces the speed to v = 2 v_s0 / (1 + m_b/m_s + (5/2) sin^2 theta); pass ``mu0`` to use
5.4's mu = mu0 sin(theta) instead. The vertical part of v_b goes into the table and is dropped.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from poolgame.physics.constants import (BALL_INERTIA, BALL_MASS, BALL_RADIUS, CUE_LENGTH,
                                        CUE_TIP_TO_CENTRE, EXACT, Constants)


@dataclass(frozen=True)
class Shot:
    """A cue strike. ``angle``: cue direction in the table plane, radians counter-clockwise from
    +x towards +z; ``speed``: cue speed in m/s; ``tip_x`` (right) and ``tip_y`` (up): tip offset
    from the cue line through the ball centre, in ball radii; ``elevation``: cue butt raised
    by this many radians."""

    angle: float
    speed: float
    tip_x: float = 0.0
    tip_y: float = 0.0
    elevation: float = 0.0


def cue_frame(shot: Shot):
    """3-D (x, y, z) unit vectors: cue direction d, right, up (perpendicular to d)."""
    ce = math.cos(shot.elevation)
    d = np.array([ce * math.cos(shot.angle), -math.sin(shot.elevation), ce * math.sin(shot.angle)])
    right = np.cross(d, [0.0, 1.0, 0.0])
    right /= np.linalg.norm(right)
    return d, right, np.cross(right, d)


def strike(shot: Shot, mu0: float | None = None, k: Constants = EXACT):
    """Ball state after the strike: (v, w, wy) with v, w 2-D in m/s, wy = R omega_y in m/s; the cue's
    mass is m_b / ``k.mass_ratio``."""
    if shot.tip_x**2 + shot.tip_y**2 >= 1.0:
        raise ValueError("the tip offset must lie inside the ball")
    d, right, up = cue_frame(shot)
    cos_t = math.sqrt(1.0 - shot.tip_x**2 - shot.tip_y**2)
    sin_t = math.hypot(shot.tip_x, shot.tip_y)
    n = cos_t * d - shot.tip_x * right - shot.tip_y * up
    t = (d - cos_t * n) / sin_t if sin_t > 0.0 else np.zeros(3)
    mu = math.tan(math.asin(sin_t)) if mu0 is None else mu0 * sin_t
    cue_mass = BALL_MASS / k.mass_ratio
    cue_inertia = cue_mass * CUE_LENGTH**2 / 12
    denominator = ((1 + mu * mu) / (2 * cue_mass) + (1 + mu * mu) / (2 * BALL_MASS)
                   + CUE_TIP_TO_CENTRE**2 * (mu * cos_t - sin_t) ** 2 / (2 * cue_inertia)
                   + BALL_RADIUS**2 * mu * mu / (2 * BALL_INERTIA))
    j = shot.speed * (cos_t + mu * sin_t) / denominator
    v = j / BALL_MASS * (n + mu * t)
    omega = BALL_RADIUS * mu * j / BALL_INERTIA * np.cross(t, n)
    # w = R (omega x y) = R (-omega_z, omega_x); wy = R omega_y
    w = BALL_RADIUS * np.array([-omega[2], omega[0]])
    return np.array([v[0], v[2]]), w, BALL_RADIUS * omega[1]
