"""Ball-ball collision (errata 3.x): equal masses, frictionless, restitution e (1 = elastic).
n = (r_b - r_a)/|r_b - r_a|, s = (v_a - v_b).n; no collision when s <= 0; otherwise
v_a' = v_a - (1+e)/2 s n, v_b' = v_b + (1+e)/2 s n. Spins are unchanged."""
from __future__ import annotations

import numpy as np


def collide(r_a, v_a, r_b, v_b, restitution: float = 1.0):
    """New (v_a, v_b); the inputs unchanged when the balls separate."""
    d = np.asarray(r_b, float) - np.asarray(r_a, float)
    n = d / np.linalg.norm(d)
    s = float(np.dot(np.asarray(v_a) - np.asarray(v_b), n))
    if s <= 0.0:
        return np.array(v_a, float), np.array(v_b, float)
    j = 0.5 * (1.0 + restitution) * s
    return v_a - j * n, v_b + j * n
