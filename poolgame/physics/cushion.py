"""Ball-cushion collision (errata 4.x, Coulomb form with a stick limit), the contact at the
ball's equator. n = cushion normal pointing into the table, t = y x n:
v_n' = -e v_n; slip along the rail s = v.t - wy; dv_t = -min(mu_c (1+e)|v_n|, (2/7)|s|) sign(s);
the spin change (5/2R)(dv_t t x n) is dwy = -(5/2) dv_t. The horizontal spin w is unchanged."""
from __future__ import annotations

import math

import numpy as np

from poolgame.physics.constants import CUSHION_FRICTION, CUSHION_RESTITUTION


def tangent(normal: np.ndarray) -> np.ndarray:
    """t = y x n; for n = (nx, 0, nz) that is (nz, 0, -nx)."""
    return np.array([normal[1], -normal[0]], float)


def rebound(v: np.ndarray, wy: float, normal: np.ndarray,
            restitution: float = CUSHION_RESTITUTION, friction: float = CUSHION_FRICTION):
    """New (v, wy) after hitting a cushion whose inward normal is ``normal`` (unit)."""
    t_hat = tangent(normal)
    v_n = float(np.dot(v, normal))
    v_t = float(np.dot(v, t_hat))
    s = v_t - wy
    dv_t = -math.copysign(min(friction * (1.0 + restitution) * abs(v_n), (2.0 / 7.0) * abs(s)), s)
    v_new = -restitution * v_n * normal + (v_t + dv_t) * t_hat
    return v_new, wy - 2.5 * dv_t
