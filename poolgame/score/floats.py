"""The pack's integers as float reference states, and the float searches the scoring needs: a
ball's own crossing of a rail line and the exact 2R contact of two balls, across phase ends."""
from __future__ import annotations

import math

import numpy as np

from poolgame.physics.ball import AT_REST, POCKETED, Ball, advance, advance_through
from poolgame.physics.constants import Constants
from poolgame.physics.events import ball_ball_time, rail_time
from poolgame.physics.table import RAILS
from poolgame.trajectory import PHASE, VX, VZ, WX, WY, WZ, X, Z

UM = 1e-6                          # m per um
UM_PER_TICK = 20e-6                # m/s per um/tick
RAIL_OF = {1: RAILS[0], 2: RAILS[1], 3: RAILS[2], 4: RAILS[3]}   # the pack's rail numbers


def ball_from(state, k: Constants) -> Ball:
    """A float ball from the pack's state (STATE order, um and um/tick)."""
    return Ball(np.array([state[X], state[Z]], float) * UM, np.array([state[VX], state[VZ]], float) * UM_PER_TICK,
                np.array([state[WX], state[WZ]], float) * UM_PER_TICK, state[WY] * UM_PER_TICK,
                state[PHASE] == 3, k)


def moved(ball: Ball, dt: float) -> Ball:
    """A copy of ``ball`` advanced by ``dt`` seconds without collisions (across phase ends)."""
    b = ball.copy()
    advance_through(b, dt)
    return b


def _moving(ball: Ball) -> bool:
    return ball.state not in (AT_REST, POCKETED)


def rail_crossing(ball: Ball, rail: int, horizon: float):
    """(time, ball at that time) of ``ball``'s first outward crossing of the pack's rail ``rail`` within
    ``horizon`` seconds, or None."""
    b, clock = ball.copy(), 0.0
    while clock < horizon and _moving(b):
        step = min(b.phase_duration(), horizon - clock)
        t = rail_time(b, RAIL_OF[rail], step)
        if t <= step:
            advance(b, t)
            return clock + t, b
        advance(b, step)
        clock += step
    return None


def contact(a: Ball, b: Ball, horizon: float):
    """(time, a, b) at the first exact 2R contact of two float balls approaching within ``horizon``
    seconds, or None (also when they already overlap)."""
    a, b, clock = a.copy(), b.copy(), 0.0
    if np.linalg.norm(b.r - a.r) < 2 * 0.028575 - 1e-9:
        return None
    while clock < horizon and (_moving(a) or _moving(b)):
        step = min(a.phase_duration(), b.phase_duration(), horizon - clock)
        t = ball_ball_time(a, b, step)
        if t <= step:
            advance(a, t)
            advance(b, t)
            return clock + t, a, b
        advance(a, step)
        advance(b, step)
        clock += step
    return None


def angle_between(u, v) -> float:
    """Degrees between two 2-D vectors."""
    return abs(math.degrees(math.atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1])))


def resolvable(magnitude_units: float, threshold: float) -> bool:
    """A ratio or direction is judged only where one integer unit of it fits in its threshold: a
    quantity of m units is known to about 1/m (relative, or radians)."""
    return magnitude_units * threshold >= 1.0
