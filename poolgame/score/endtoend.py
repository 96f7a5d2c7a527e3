"""End-to-end scoring: the float reference plays the whole shot from its own strike with the
pack's dequantised constants and exact event times (poolgame.physics.simulator), and the pack's
complete ticks are compared with it.

The allowances come from the strike's tolerance. The pack delivers the ball speed to within
STRIKE_SPEED (1e-4 relative, DESIGN.md section 6) and the direction to within STRIKE_DIRECTION
(1e-4 rad: its unit vectors are x 10^4). A ball that covers a path s before stopping covers a
distance proportional to v^2 (sliding and rolling decelerate at constant rates), so a speed error
dv/v moves it by up to 2 (dv/v) s along the path; a direction error moves it by up to d(theta) s
across. The float and the integers may therefore differ by EPSILON s = (2 STRIKE_SPEED +
STRIKE_DIRECTION) s on top of the seeded thresholds:
- per tick: 2 mm (the seeded per-tick max) + EPSILON s, s the path so far;
- where a lone ball stops: 1 mm + 0.05 % L (the seeded stop threshold) + EPSILON L;
- the object ball after the first contact: the cue ball may arrive EPSILON s to the side, which
  turns the line of centres of a cut at angle phi by EPSILON s / (2R cos phi): 0.1 deg + that.
After the first ball-ball contact the two shots part (each collision multiplies the difference,
DESIGN.md section 5), so positions are compared only before it; what follows is scored seeded.
"""
from __future__ import annotations

import math

import numpy as np

from poolgame.physics import cue as float_cue
from poolgame.physics.ball import Ball
from poolgame.physics.constants import BALL_RADIUS, EXACT, Constants
from poolgame.physics.simulator import simulate
from poolgame.score.floats import UM_PER_TICK, angle_between, ball_from, resolvable
from poolgame.score.metrics import METRICS
from poolgame.trajectory import PHASE, POCKETED, TICKS_PER_SECOND, VX, VZ, Trajectory

STRIKE_SPEED = 1e-4
STRIKE_DIRECTION = 1e-4
EPSILON = 2 * STRIKE_SPEED + STRIKE_DIRECTION
TICK = 1.0 / TICKS_PER_SECOND


def float_shot(trajectory: Trajectory, shot, k: Constants) -> list[Ball]:
    """The table as the pack had it before the strike, the cue ball struck by the float cue."""
    balls = [ball_from(state, k) for state in trajectory.start]
    for ball in balls:
        ball.v[:] = 0.0
        ball.w[:] = 0.0
        ball.wy = 0.0
    cue = trajectory.ids.index(0)
    v, w, wy = float_cue.strike(float_cue.Shot(math.radians(shot.angle), shot.speed, shot.tip_x, shot.tip_y,
                                               math.radians(shot.elevation)), k=k)
    balls[cue].v, balls[cue].w, balls[cue].wy = v, w, wy
    return balls


def play(balls: list[Ball], ticks: int):
    """Positions (ticks, balls, 2) in mm after each tick, and the float's events as (tick, event,
    the balls just before it, their velocities just after it)."""
    positions, events = np.zeros((ticks, len(balls), 2)), []
    for tick in range(ticks):
        simulate(balls, TICK, lambda event, before, tick=tick: events.append(
            (tick + 1, event, before, [b.v.copy() for b in balls])))
        positions[tick] = [b.r * 1000 for b in balls]
    return positions, events


def score(trajectory: Trajectory, shot, k: Constants, samples: dict, constants: bool = True) -> np.ndarray:
    """Add this shot's end-to-end samples; returns the float's positions (ticks, balls, 2) in mm."""
    n = len(trajectory.ticks)
    floats, float_events = play(float_shot(trajectory, shot, k), n)
    ints = np.array([t[:, :2] for t in trajectory.ticks], float) / 1000
    first_int = next((e for e in trajectory.events if e.kind == "ball"), None)
    first_float = next((e for e in float_events if e[1].kind == "ball"), None)
    last = min(first_int.tick if first_int else n + 1, first_float[0] if first_float else n + 1) - 1
    start = trajectory.start[:, :2] / 1000
    steps = np.linalg.norm(np.diff(np.concatenate([start[None], floats]), axis=0), axis=2)
    path = np.cumsum(steps, axis=0)                 # mm along each float ball's path
    in_play = np.array([t[:, PHASE] != POCKETED for t in trajectory.ticks])
    for tick in range(last):
        for i in np.flatnonzero(in_play[tick]):
            error = float(np.linalg.norm(ints[tick, i] - floats[tick, i]))
            samples["e2e_trajectory"].append(error / (2.0 + EPSILON * path[tick, i]))
    cue = trajectory.ids.index(0)
    if last == n and n and trajectory.ticks[-1][cue, PHASE] == 0:
        error = float(np.linalg.norm(ints[-1, cue] - floats[-1, cue]))
        samples["e2e_stop"].append(error / (1.0 + (0.0005 + EPSILON) * path[-1, cue]))
    if first_int is not None and first_float is not None:
        _first_contact(trajectory, first_int, first_float, path, samples)
    if constants and last > 0:
        _constants_alone(trajectory, shot, floats[:last], samples)
    return floats


def _first_contact(trajectory, first_int, first_float, path, samples: dict) -> None:
    tick, event, before, after_v = first_float
    pair = sorted(event.balls)
    seen = sorted([first_int.ball, first_int.partner]) if first_int.partner is not None else None
    if seen != pair:
        return
    a, b = before[pair[0]], before[pair[1]]
    obj, cue = (pair[1], pair[0]) if np.linalg.norm(b.v) <= np.linalg.norm(a.v) else (pair[0], pair[1])
    change_float = (after_v[obj] - before[obj].v) / UM_PER_TICK       # the impulse's direction
    if not resolvable(np.linalg.norm(change_float), math.radians(METRICS["object_direction"].high)):
        return
    after = next(e for e in trajectory.events if e.tick == first_int.tick and e.ball == obj)
    change_int = np.array([after.state[VX], after.state[VZ]], float) - trajectory.start[obj, VX:VZ + 1]
    normal, v_cue = before[obj].r - before[cue].r, before[cue].v - before[obj].v
    cos_cut = abs(float(normal @ v_cue)) / (np.linalg.norm(normal) * max(np.linalg.norm(v_cue), 1e-12))
    lateral = EPSILON * path[tick - 1, cue] / 1000      # m
    allowance = 0.1 + math.degrees(lateral / (2 * BALL_RADIUS * max(cos_cut, 1e-9)))
    samples["e2e_object_direction"].append(angle_between(change_int, change_float) / allowance)


def _constants_alone(trajectory, shot, pack_floats, samples: dict) -> None:
    """The float with the seed's exact constants against the float with the pack's: what quantising
    the constants costs before any integer arithmetic."""
    exact, _ = play(float_shot(trajectory, shot, EXACT), len(pack_floats))
    difference = np.linalg.norm(exact - pack_floats, axis=2)
    samples["constants_trajectory"].append(float(difference.max()))
    samples["constants_stop"].append(float(difference[-1].max()))
