"""Event-driven simulation of a shot: find the earliest event (a phase end, ball-ball contact,
cushion, pocket), advance every ball to it, resolve it, repeat."""
from __future__ import annotations

from dataclasses import dataclass

from poolgame.physics import ball_ball, cushion
from poolgame.physics.ball import AT_REST, POCKETED, Ball, advance
from poolgame.physics.constants import TICKS_PER_SECOND
from poolgame.physics.events import ball_ball_time, rail_time
from poolgame.physics.table import RAILS

MAX_EVENTS = 100_000


@dataclass(frozen=True)
class Event:
    time: float
    kind: str          # "transition", "ball", "cushion", "pocket"
    balls: tuple       # indices
    rail: str = ""


def _next_event(balls: list[Ball], horizon: float) -> tuple[float, tuple]:
    """(time, (kind, i, j_or_rail)) of the earliest event before ``horizon``."""
    best = (horizon, ("end",))
    moving = [i for i, b in enumerate(balls) if b.state not in (AT_REST, POCKETED)]
    in_play = [i for i, b in enumerate(balls) if not b.pocketed]
    for i in moving:
        ball = balls[i]
        t = ball.phase_duration()
        if t < best[0]:
            best = (t, ("transition", i))
        for rail in RAILS:
            t = rail_time(ball, rail, best[0])
            if t < best[0]:
                best = (t, ("rail", i, rail))
        for j in in_play:
            if j != i and (j not in moving or j > i):
                t = ball_ball_time(ball, balls[j], best[0])
                if t < best[0]:
                    best = (t, ("ball", i, j))
    return best


def _resolve(balls: list[Ball], time: float, what: tuple) -> Event:
    kind = what[0]
    if kind == "transition":
        return Event(time, "transition", (what[1],))
    if kind == "ball":
        a, b = balls[what[1]], balls[what[2]]
        a.v, b.v = ball_ball.collide(a.r, a.v, b.r, b.v)
        return Event(time, "ball", (what[1], what[2]))
    ball, rail = balls[what[1]], what[2]
    if rail.pocketed_at(ball.r):
        ball.pocketed = True
        ball.v[:] = 0.0
        ball.w[:] = 0.0
        ball.wy = 0.0
        return Event(time, "pocket", (what[1],), rail.name)
    ball.v, ball.wy = cushion.rebound(ball.v, ball.wy, rail.normal, ball.k.cushion_restitution,
                                      ball.k.cushion_friction)
    return Event(time, "cushion", (what[1],), rail.name)


def simulate(balls: list[Ball], duration: float, on_event=None) -> list[Event]:
    """Run ``duration`` seconds (or until every ball rests), mutating ``balls``; returns events.
    ``on_event(event, before)`` hears each event after its resolution, with copies of the balls
    just before it."""
    events: list[Event] = []
    clock = 0.0
    while clock < duration and any(b.state not in (AT_REST, POCKETED) for b in balls):
        if len(events) >= MAX_EVENTS:
            raise RuntimeError(f"more than {MAX_EVENTS} events: the simulation does not settle")
        dt, what = _next_event(balls, duration - clock)
        for ball in balls:
            advance(ball, dt)
        clock += dt
        if what[0] != "end":
            before = [b.copy() for b in balls] if on_event is not None else None
            events.append(_resolve(balls, clock, what))
            if on_event is not None:
                on_event(events[-1], before)
    return events


def simulate_ticks(balls: list[Ball], ticks: int) -> list[list[Ball]]:
    """Snapshots of every ball at the end of each tick (20 per second)."""
    snapshots = []
    for _ in range(ticks):
        simulate(balls, 1.0 / TICKS_PER_SECOND)
        snapshots.append([b.copy() for b in balls])
    return snapshots

