"""Rolling (pool-models 1.2 with the rolling coefficient, errata): a straight line with constant
deceleration mu_r g along v_hat; w = v throughout."""
from __future__ import annotations

import numpy as np

from poolgame.physics.constants import ROLL_DECELERATION


def roll_duration(v: np.ndarray, deceleration: float = ROLL_DECELERATION) -> float:
    return float(np.linalg.norm(v)) / deceleration


def roll_acceleration(v: np.ndarray, deceleration: float = ROLL_DECELERATION) -> np.ndarray:
    speed = float(np.linalg.norm(v))
    return np.zeros(2) if speed == 0.0 else -deceleration * v / speed


def roll(r: np.ndarray, v: np.ndarray, t: float, deceleration: float = ROLL_DECELERATION):
    """State after rolling for t <= the roll duration: (r, v)."""
    a = roll_acceleration(v, deceleration)
    return r + v * t + 0.5 * a * t * t, v + a * t
