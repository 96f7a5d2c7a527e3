"""A ball's state and its motion between events: sliding -> rolling -> at rest, with the
side spin decaying independently. The state is always the one at the simulator's clock."""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from poolgame.physics import rolling, sliding, spin
from poolgame.physics.constants import BALL_MASS, EXACT, Constants

SLIDING, ROLLING, AT_REST, POCKETED = "sliding", "rolling", "at rest", "pocketed"
# below this slip or speed (m/s) a phase is over: round-off, not motion
EPSILON = 1e-12


@dataclass
class Ball:
    r: np.ndarray
    v: np.ndarray = field(default_factory=lambda: np.zeros(2))
    w: np.ndarray = field(default_factory=lambda: np.zeros(2))
    wy: float = 0.0
    pocketed: bool = False
    k: Constants = EXACT          # the constants this ball moves with


    def __post_init__(self) -> None:
        self.r = np.asarray(self.r, float)
        self.v = np.asarray(self.v, float)
        self.w = np.asarray(self.w, float)

    def copy(self) -> "Ball":
        return Ball(self.r.copy(), self.v.copy(), self.w.copy(), self.wy, self.pocketed, self.k)

    @property
    def state(self) -> str:
        if self.pocketed:
            return POCKETED
        v, w = self.v, self.w
        if math.hypot(v[0] - w[0], v[1] - w[1]) > EPSILON:
            return SLIDING
        return ROLLING if math.hypot(v[0], v[1]) > EPSILON else AT_REST

    def phase_duration(self) -> float:
        state = self.state
        if state == SLIDING:
            return sliding.slide_duration(self.v, self.w, self.k.slide_deceleration)
        if state == ROLLING:
            return rolling.roll_duration(self.v, self.k.roll_deceleration)
        return math.inf

    def acceleration(self) -> np.ndarray:
        state = self.state
        if state == SLIDING:
            return sliding.slide_accelerations(self.v, self.w, self.k.slide_deceleration)[0]
        if state == ROLLING:
            return rolling.roll_acceleration(self.v, self.k.roll_deceleration)
        return np.zeros(2)

    def kinetic_energy(self) -> float:
        """Translation plus rotation, I = (2/5) m R^2: (m/2)(v^2 + (2/5)(|w|^2 + wy^2))."""
        return 0.5 * BALL_MASS * (self.v @ self.v + 0.4 * (self.w @ self.w + self.wy * self.wy))


def advance(ball: Ball, dt: float) -> None:
    """Move ``ball`` forward by ``dt`` (at most its phase duration; the end of a phase snaps to the
    closed-form state that follows it)."""
    k = ball.k
    ball.wy = spin.decay_side_spin(ball.wy, dt, k.spin_deceleration)
    state = ball.state
    duration = ball.phase_duration()
    if state == SLIDING:
        if dt >= duration:
            v_roll = sliding.rolling_velocity(ball.v, ball.w)
            ball.r = sliding.slide(ball.r, ball.v, ball.w, duration, k.slide_deceleration)[0]
            ball.v, ball.w = v_roll, v_roll.copy()
        else:
            ball.r, ball.v, ball.w = sliding.slide(ball.r, ball.v, ball.w, dt, k.slide_deceleration)
    elif state == ROLLING:
        ball.r, ball.v = rolling.roll(ball.r, ball.v, min(dt, duration), k.roll_deceleration)
        if dt >= duration:
            ball.v = np.zeros(2)
        ball.w = ball.v.copy()


def advance_through(ball: Ball, dt: float) -> None:
    """Advance by any ``dt``, crossing phase ends (no collisions)."""
    while dt > 0.0 and ball.state in (SLIDING, ROLLING):
        step = min(dt, ball.phase_duration())
        advance(ball, step)
        dt -= step
    if dt > 0.0:
        ball.wy = spin.decay_side_spin(ball.wy, dt, ball.k.spin_deceleration)
