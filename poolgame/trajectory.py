"""What the pool pack did during a shot, read from its scores: every ball's state after each
complete physics tick, and the events it resolved.

A tick the pack carries over (``$carry pool.game``) is mid-computation and is not read. The pack
saves a ball's state at its last event of the tick (``pool.bt``, the time in 1/10000 tick, and
``pool.bx`` ... ``pool.bstate``: pool:physics/events/save), so each ball's last event of a tick is
seen exactly, after its resolution; an earlier event of the same ball in the same tick is not. A
tick whose events were not all seen (the pack's own count, ``#events.count pool.tmp``, is larger)
(or with a ball-ball event whose partner is not seen at the same time: the partner met something
else later in the tick) is marked, so that its events are not judged from the wrong starting state.
Units are the pack's (pool:load's header): um, um/tick, 1/10000 tick.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

STATE = ("x", "z", "vx", "vz", "wx", "wz", "wy", "state")
SAVED = ("bx", "bz", "bvx", "bvz", "bwx", "bwz", "bwy", "bstate")
X, Z, VX, VZ, WX, WZ, WY, PHASE = range(len(STATE))
POCKETED = 3
TICK_FRACTION = 10_000            # pool.bt units per tick
TICKS_PER_SECOND = 20


@dataclass(frozen=True)
class Event:
    """One ball's last event in a physics tick, after its resolution."""

    tick: int                     # the physics tick it happened in (1 = the first after the strike)
    ball: int                     # index into Trajectory.ids
    fraction: int                 # its time within the tick, 1/10000 tick
    state: tuple                  # the ball's state right after it (STATE order)
    kind: str                     # "ball", "cushion", "pocket"
    rail: int = 0                 # 1 x = R, 2 x = L - R, 3 z = R, 4 z = W - R (kind "cushion")
    partner: int | None = None    # the other ball's index (kind "ball"), when its event is seen too

    @property
    def time(self) -> float:
        """Seconds after the strike."""
        return (self.tick - 1 + self.fraction / TICK_FRACTION) / TICKS_PER_SECOND

    def to_json(self, ids) -> dict:
        extra = {"rail": self.rail} if self.kind == "cushion" else {}
        if self.partner is not None:
            extra["partner"] = ids[self.partner]
        return {"tick": self.tick, "time_s": round(self.time, 6), "ball": ids[self.ball], "kind": self.kind,
                "x_mm": self.state[X] / 1000, "z_mm": self.state[Z] / 1000, **extra}


class Trajectory:
    """Read after the strike (``start``), then :meth:`observe` after each complete physics tick."""

    def __init__(self, emu, holders: dict[int, str]) -> None:
        self.ids = sorted(holders)
        self.summoned = list(holders)               # ball ids in entity (summon) order
        self._holders = [holders[i] for i in self.ids]
        self._rails = tuple(emu.score(name, "pool.const") for name in ("$R", "$L", "$W"))
        self.start = self._read(emu, STATE)
        self.ticks: list[np.ndarray] = []          # (balls, STATE) after each complete physics tick
        self.rolling: list[np.ndarray] = []        # (balls, 2): pool.rx pool.rz, a slide's rolling velocity
        self.events: list[Event] = []
        self.unseen: set[int] = set()              # ticks with more events than were seen
        self._saved = self._read(emu, ("bt", *SAVED))

    def _read(self, emu, names) -> np.ndarray:
        return emu.score_block(self._holders, [f"pool.{n}" for n in names])

    def observe(self, emu, count: int) -> None:
        """Read the balls after a complete physics tick in which the pack resolved ``count`` events."""
        previous = self.ticks[-1] if self.ticks else self.start
        block = self._read(emu, (*STATE, "bt", *SAVED, "rx", "rz"))     # one read of every score
        n = len(STATE)
        now, saved = block[:, :n], block[:, n:2 * n + 1]
        self.ticks.append(now)
        self.rolling.append(block[:, 2 * n + 1:])
        tick = len(self.ticks)
        # pool:physics/events/begin saves each moving ball at time 0: an event is a new save (a ball
        # that stopped keeps its last one) made later in the tick, or at time 0 somewhere else than
        # where the ball was
        fresh = (saved != self._saved).any(axis=1) & ((saved[:, 0] > 0) | (saved[:, 1:] != previous).any(axis=1))
        dropped = (now[:, PHASE] == POCKETED) & (previous[:, PHASE] != POCKETED)
        found = []
        for i in np.flatnonzero(fresh | dropped).tolist():
            if fresh[i]:
                found.append((i, int(saved[i, 0]), tuple(saved[i, 1:].tolist())))
            else:
                found.append((i, int(saved[i, 0]), tuple(now[i].tolist())))
        self._saved = saved
        events = self._classify(tick, found)
        seen = sum(1 for e in events if e.kind != "ball" or e.partner is None or e.ball < e.partner)
        # a ball event without its partner: the partner's save was overwritten by a later event of
        # its own (or several balls met at one instant), so that earlier event went unseen
        if seen != count or any(e.kind == "ball" and e.partner is None for e in events):
            self.unseen.add(tick)
        self.events.extend(events)

    def _classify(self, tick: int, found) -> list[Event]:
        r, length, width = self._rails
        lines = {1: (X, r), 2: (X, length - r), 3: (Z, r), 4: (Z, width - r)}
        events = []
        for i, bt, state in found:
            if state[PHASE] == POCKETED:
                events.append(Event(tick, i, bt, state, "pocket"))
                continue
            rail = next((k for k, (axis, value) in lines.items() if state[axis] == value), 0)
            if rail:
                events.append(Event(tick, i, bt, state, "cushion", rail))
                continue
            partners = [j for j, t, s in found if j != i and t == bt and s[PHASE] != POCKETED]
            events.append(Event(tick, i, bt, state, "ball", partner=partners[0] if len(partners) == 1 else None))
        return events

    def positions_mm(self) -> np.ndarray:
        """(ticks + 1, balls, 2): the start, then each complete physics tick, in mm."""
        return np.array([self.start[:, :2], *(t[:, :2] for t in self.ticks)], float) / 1000

    def to_json(self) -> dict:
        return {"ids": self.ids, "positions_mm": self.positions_mm().round(3).tolist(),
                "events": [e.to_json(self.ids) for e in self.events]}
