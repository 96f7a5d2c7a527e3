"""Swept event detection: when, within a horizon, a ball's quadratic path (constant acceleration
over its current phase) first touches another ball or reaches a rail line."""
from __future__ import annotations

import math

import numpy as np

from poolgame.physics.ball import Ball
from poolgame.physics.constants import BALL_RADIUS
from poolgame.physics.table import Rail

# a root this far before "now" still counts: it is the contact just reached, not a past one
TOLERANCE = 1e-12


def _earliest_root(coefficients, derivative, horizon: float) -> float:
    """Smallest real root t in [0, horizon] of the polynomial (highest power first) at which
    ``derivative(t) < 0`` (approaching); inf when none."""
    coefficients = np.trim_zeros(np.asarray(coefficients, float), "f")
    if coefficients.size < 2:
        return math.inf
    best = math.inf
    polynomial = np.poly1d(coefficients)
    slope = polynomial.deriv()
    for root in np.roots(coefficients):
        if abs(root.imag) > 1e-9 * max(1.0, abs(root.real)):
            continue
        t = root.real
        for _ in range(3):  # polish: np.roots of a quartic loses digits near double roots
            d = slope(t)
            if d != 0.0:
                t -= polynomial(t) / d
        if -TOLERANCE <= t <= horizon and t < best and derivative(max(t, 0.0)) < 0.0:
            best = max(t, 0.0)
    return best


def ball_ball_time(a: Ball, b: Ball, horizon: float) -> float:
    """First time |r_b - r_a| = 2R while approaching, within ``horizon`` (inf if none)."""
    c = b.r - a.r
    bv = b.v - a.v
    half_a = 0.5 * (b.acceleration() - a.acceleration())
    # the gap cannot close by more than |bv| h + |half_a| h^2 within the horizon: no root to look for
    reach = math.hypot(*bv) * horizon + math.hypot(*half_a) * horizon * horizon
    if math.hypot(*c) - 2 * BALL_RADIUS > reach + TOLERANCE:
        return math.inf
    quartic = [half_a @ half_a, 2 * half_a @ bv, bv @ bv + 2 * half_a @ c, 2 * bv @ c,
               c @ c - (2 * BALL_RADIUS) ** 2]

    def approach(t: float) -> float:
        return (c + bv * t + half_a * t * t) @ (bv + 2 * half_a * t)

    return _earliest_root(quartic, approach, horizon)


def rail_time(ball: Ball, rail: Rail, horizon: float) -> float:
    """First time the ball centre reaches the rail line moving outwards (inf if none)."""
    distance = rail.distance(ball.r)
    speed = float(rail.normal @ ball.v)
    half_a = 0.5 * float(rail.normal @ ball.acceleration())
    if distance > (abs(speed) + abs(half_a) * horizon) * horizon + TOLERANCE:
        return math.inf
    return _earliest_root([half_a, speed, distance], lambda t: speed + 2 * half_a * t, horizon)
