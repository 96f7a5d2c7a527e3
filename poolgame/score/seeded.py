"""Seeded scoring: the float reference restarts from the pack's integer state after the strike and
after each event the pack resolved, so each segment between events scores the table arithmetic
alone (DESIGN.md section 6). Only complete physics ticks are read (poolgame.trajectory).

Each ball is followed separately: between its events it only moves (slides, rolls, spins down),
and each event of the pack starts it again from the integers right after the resolution. The
events themselves are judged at resolution: a cushion against the float's own crossing of the
rail line (rebound angle, normal-speed ratio); a ball-ball contact by its centre distance and by
the object ball's direction against the exact 2R contact of the two float paths.
"""
from __future__ import annotations

import math
from collections import defaultdict

import numpy as np

from poolgame.physics import ball_ball, cushion, sliding
from poolgame.physics.ball import SLIDING
from poolgame.physics.constants import BALL_RADIUS, Constants
from poolgame.score.floats import (RAIL_OF, UM_PER_TICK, angle_between, ball_from, contact, moved, rail_crossing,
                                   resolvable)
from poolgame.score.metrics import METRICS
from poolgame.trajectory import PHASE, POCKETED, TICKS_PER_SECOND, VX, VZ, WX, WY, WZ, X, Z, Trajectory

TICK = 1.0 / TICKS_PER_SECOND
AT_REST_PHASE, SLIDING_PHASE = 0, 1


class _Segment:
    """A ball's float path from one seed (the strike or an event) to the next."""

    def __init__(self, seed, t_seed: float, first_tick: int, rolling) -> None:
        self.seed, self.t_seed = seed, t_seed
        self.first_tick = first_tick      # the complete tick of errors[0] and phases[0]
        self.rolling = rolling            # the pack's rolling velocity of a slide started here (um/tick)
        self.errors: list[float] = []     # mm, at each complete tick
        self.path = [seed.r.copy()]
        self.phases: list[int] = []

    def at(self, t: float):
        return moved(self.seed, t - self.t_seed)


def score(trajectory: Trajectory, k: Constants, samples: dict) -> dict:
    """Add this shot's seeded samples to ``samples`` (metric key -> list); returns per-tick float
    positions (ticks, balls, 2) in mm for the plots."""
    n, balls = len(trajectory.ticks), len(trajectory.ids)
    by_tick = defaultdict(list)
    for event in trajectory.events:
        by_tick[event.tick].append(event)
    # the rolling velocity the strike set is still there after tick 1 unless the ball met something
    hit_at_once = {e.ball for e in by_tick.get(1, [])}
    segments = [_Segment(ball_from(trajectory.start[i], k), 0.0, 1,
                         None if i in hit_at_once or not n else trajectory.rolling[0][i]) for i in range(balls)]
    floats = np.full((n, balls, 2), np.nan)
    for tick in range(1, n + 1):
        now = trajectory.ticks[tick - 1]
        events = by_tick.get(tick, [])
        if tick not in trajectory.unseen:
            _score_events(events, segments, k, samples)
        for event in events:
            _close(segments[event.ball], samples, stopped=False)
            segments[event.ball] = _Segment(ball_from(event.state, k), event.time, tick,
                                            trajectory.rolling[tick - 1][event.ball])
        for i, segment in enumerate(segments):
            if now[i, PHASE] == POCKETED or segment.seed.pocketed:
                continue
            f = segment.at(tick * TICK)
            floats[tick - 1, i] = f.r * 1000
            segment.path.append(f.r.copy())
            segment.phases.append(int(now[i, PHASE]))
            segment.errors.append(float(np.hypot(*(now[i, :2] / 1000 - f.r * 1000))))
    final = trajectory.ticks[-1] if n else trajectory.start
    for i, segment in enumerate(segments):
        _close(segment, samples, stopped=final[i, PHASE] == AT_REST_PHASE, final=final[i])
    return floats


def _close(segment: _Segment, samples: dict, stopped: bool, final=None) -> None:
    moving = bool(np.any(segment.seed.v) or np.any(segment.seed.w))
    if segment.errors and moving:
        errors = np.array(segment.errors)
        samples["trajectory_rms"].append(float(np.sqrt(np.mean(errors ** 2))))
        samples["trajectory_max"].append(float(errors.max()))
    _slide_to_roll(segment, samples)
    if stopped and final is not None and moving:
        rest = moved(segment.seed, 1e3)
        path = sum(np.linalg.norm(b - a) for a, b in zip(segment.path, segment.path[1:]))
        path += float(np.linalg.norm(rest.r - segment.path[-1]))
        error_mm = float(np.hypot(*(final[:2] / 1000 - rest.r * 1000)))
        samples["stop"].append(error_mm / (1.0 + 0.0005 * path * 1000))


def _slide_to_roll(segment: _Segment, samples: dict) -> None:
    seed = segment.seed
    if seed.state != SLIDING:
        return
    if segment.rolling is not None:
        v_roll = sliding.rolling_velocity(seed.v, seed.w) / UM_PER_TICK
        samples["roll_velocity"].extend(float(abs(a - b)) for a, b in zip(segment.rolling, v_roll))
    ends = segment.t_seed + seed.phase_duration()
    float_tick = math.ceil(ends * TICKS_PER_SECOND - 1e-9)      # the tick in which the slide ends
    ended = [segment.first_tick + j for j, phase in enumerate(segment.phases) if phase != SLIDING_PHASE]
    if ended and float_tick < segment.first_tick + len(segment.phases):
        samples["transition_tick"].append(float(abs(ended[0] - float_tick)))


def _score_events(events, segments, k: Constants, samples: dict) -> None:
    for event in events:
        segment = segments[event.ball]
        if event.kind == "cushion":
            _cushion(event, segment, k, samples)
        elif event.kind == "ball" and event.partner is not None and event.ball < event.partner:
            partner = next((e for e in events if e.ball == event.partner), None)
            if partner is not None:
                _ball_ball(event, partner, segment, segments[event.partner], samples)


def _cushion(event, segment: _Segment, k: Constants, samples: dict) -> None:
    """The rebound at the float's own crossing of the rail against the pack's resolution."""
    found = rail_crossing(segment.seed, event.rail, event.time - segment.t_seed + TICK)
    if found is None or abs(segment.t_seed + found[0] - event.time) > TICK:
        return                        # an earlier event of this ball in the same tick went unseen
    before = found[1]
    normal = RAIL_OF[event.rail].normal
    v_float, _ = cushion.rebound(before.v, before.wy, normal, k.cushion_restitution, k.cushion_friction)
    v_int = np.array([event.state[VX], event.state[VZ]], float)
    v_units = np.linalg.norm(v_float) / UM_PER_TICK
    if resolvable(v_units, math.radians(METRICS["rebound_angle"].high)):
        samples["rebound_angle"].append(angle_between(v_int, v_float))
    v_in = -float(before.v @ normal) / UM_PER_TICK
    if resolvable(v_in, METRICS["normal_ratio"].high):
        ratio = float(v_int @ normal) / v_in
        samples["normal_ratio"].append(abs(ratio / k.cushion_restitution - 1))


def _ball_ball(a_event, b_event, a: _Segment, b: _Segment, samples: dict) -> None:
    r_a = np.array([a_event.state[X], a_event.state[Z]], float)
    r_b = np.array([b_event.state[X], b_event.state[Z]], float)
    samples["contact"].append((float(np.linalg.norm(r_b - r_a)) - 2 * BALL_RADIUS * 1e6) / 1000)
    start = max(a.t_seed, b.t_seed)
    found = contact(a.at(start), b.at(start), a_event.time - start + TICK)
    if found is None or abs(start + found[0] - a_event.time) > TICK:
        return                        # overlapping float paths, or an unseen earlier event
    _, fa, fb = found
    va, vb = ball_ball.collide(fa.r, fa.v, fb.r, fb.v)
    # the object ball: the slower one before the contact; its direction is that of the impulse it
    # received (its velocity change), which the contact normal alone sets
    (obj, before, after) = (b_event, fb, vb) if np.linalg.norm(fb.v) <= np.linalg.norm(fa.v) else (a_event, fa, va)
    change_float = (after - before.v) / UM_PER_TICK
    change_int = np.array([obj.state[VX], obj.state[VZ]], float) - before.v / UM_PER_TICK
    if resolvable(np.linalg.norm(change_float), math.radians(METRICS["object_direction"].high)):
        samples["object_direction"].append(angle_between(change_int, change_float))


def energy(trajectory: Trajectory, samples: dict) -> None:
    """The integer kinetic energy (v^2 + (2/5)(w^2 + wy^2) over the balls in play) between complete
    ticks: it never rises, but in a tick with a ball-ball collision (rounded normal) by 1e-3."""
    def ke(state):
        s = state[state[:, PHASE] != POCKETED].astype(float)
        return float(np.sum(s[:, VX] ** 2 + s[:, VZ] ** 2 + 0.4 * (s[:, WX] ** 2 + s[:, WZ] ** 2 + s[:, WY] ** 2)))

    collisions = {e.tick for e in trajectory.events if e.kind == "ball"}
    previous = ke(trajectory.start)
    for tick, state in enumerate(trajectory.ticks, 1):
        now = ke(state)
        if previous > 0:
            key = "energy_rise_collision" if tick in collisions else "energy_rise"
            samples[key].append((now - previous) / previous)
        previous = now
