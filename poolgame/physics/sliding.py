"""Sliding (pool-models 2.1-2.5, spin by errata 2.6): the slip u = v - w keeps its direction,
du/dt = -(7/2) mu_s g u_hat, and sliding ends at tau = 2|u0| / (7 mu_s g)."""
from __future__ import annotations

import numpy as np

from poolgame.physics.constants import SLIDE_DECELERATION


def slip(v: np.ndarray, w: np.ndarray) -> np.ndarray:
    return v - w


def slide_duration(v: np.ndarray, w: np.ndarray, deceleration: float = SLIDE_DECELERATION) -> float:
    return 2.0 * float(np.linalg.norm(slip(v, w))) / (7.0 * deceleration)


def rolling_velocity(v: np.ndarray, w: np.ndarray) -> np.ndarray:
    """Velocity when sliding ends: v0 - (2/7) u0 (a stun shot keeps 5/7 of its speed)."""
    return v - (2.0 / 7.0) * slip(v, w)


def slide_accelerations(v: np.ndarray, w: np.ndarray,
                        deceleration: float = SLIDE_DECELERATION) -> tuple[np.ndarray, np.ndarray]:
    """(dv/dt, dw/dt) = (-mu_s g u_hat, +(5/2) mu_s g u_hat)."""
    u = slip(v, w)
    norm = float(np.linalg.norm(u))
    if norm == 0.0:
        return np.zeros(2), np.zeros(2)
    u_hat = u / norm
    return -deceleration * u_hat, 2.5 * deceleration * u_hat


def slide(r: np.ndarray, v: np.ndarray, w: np.ndarray, t: float, deceleration: float = SLIDE_DECELERATION):
    """State after sliding for t <= tau: (r, v, w)."""
    a_v, a_w = slide_accelerations(v, w, deceleration)
    return r + v * t + 0.5 * a_v * t * t, v + a_v * t, w + a_w * t
