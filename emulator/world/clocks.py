"""The world clocks of a 26.1+ world: each clock's ticks, the fraction of a tick its rate has
carried, its rate and whether it is paused (ServerClockManager.ClockInstance, 26.1.2), and the
arithmetic the ``time`` command does on them.

The overworld clock's ticks are the world's day time (:attr:`WorldState.daytime`, which
predicates' ``time_check`` and test environments read and set): one number, as the game's
Level.getOverworldClockTime reads the clock. A clock's ticks never go below 0
(ServerClockManager.addTicks).
"""
from __future__ import annotations

import math

import numpy as np

from mcfunction_parser.pack.clocks import OVERWORLD, Clocks

F32 = np.float32


class _Clock:
    __slots__ = ("ticks", "partial", "rate", "paused")

    def __init__(self) -> None:
        self.ticks = 0
        self.partial = F32(0.0)
        self.rate = F32(1.0)
        self.paused = False


class WorldClocks:
    def __init__(self, state, registry: Clocks) -> None:
        self.state = state
        self.registry = registry
        self.instances = {clock: _Clock() for clock in registry.clocks}
        self.markers = {clock: registry.markers(clock) for clock in registry.clocks}

    def __contains__(self, clock: str) -> bool:
        return clock in self.instances

    def ticks(self, clock: str) -> int:
        return self.state.daytime if clock == OVERWORLD else self.instances[clock].ticks

    def _set(self, clock: str, ticks: int) -> None:
        if clock == OVERWORLD:
            self.state.daytime = ticks
        else:
            self.instances[clock].ticks = ticks

    def set_ticks(self, clock: str, ticks: int) -> None:
        """ServerClockManager.setTotalTicks: the fraction carried is dropped."""
        self._set(clock, ticks)
        self.instances[clock].partial = F32(0.0)

    def add_ticks(self, clock: str, ticks: int) -> int:
        """ServerClockManager.addTicks (the fraction kept); returns the new ticks."""
        self._set(clock, max(self.ticks(clock) + ticks, 0))
        return self.ticks(clock)

    def move_to_marker(self, clock: str, marker: str) -> bool:
        """ServerClockManager.moveToTimeMarker: to the marker's ticks (a marker of a timeline without
        a period), or forward to its next occurrence, a whole period on when the clock is at it
        (ClockTimeMarker.resolveTimeToMoveTo). False for a marker the clock's timelines lack."""
        found = self.markers[clock].get(marker)
        if found is None:
            return False
        at, period = found
        ticks = self.ticks(clock)
        if period is None:
            ticks = at
        else:
            duration = at - ticks % period
            ticks += duration if duration > 0 else period + duration
        self.set_ticks(clock, ticks)
        return True

    def tick(self) -> None:
        """ServerClockManager.tick, once per server tick after the tick functions (when the
        ``advance_time`` rule is on): each running clock adds its rate to the fraction it carries
        and moves by the whole ticks of it (ClockInstance.tick, float arithmetic)."""
        if not self.state.gamerules.daylight_cycle:
            return
        for clock, instance in self.instances.items():
            if instance.paused:
                continue
            partial = F32(instance.partial + instance.rate)
            whole = math.floor(partial)  # Mth.floor
            instance.partial = F32(partial - F32(whole))
            if whole:
                self._set(clock, self.ticks(clock) + whole)

    def steady(self) -> bool:
        """Whether each clock moves by exactly 0 (paused) or 1 tick per tick: a rate of 1 and no
        fraction carried, so a batch of quiet ticks may move them all at once."""
        return all(c.paused or (c.rate == 1.0 and c.partial == 0.0) for c in self.instances.values())

    def snapshot(self) -> dict[str, int]:
        return {clock: self.ticks(clock) for clock in self.instances}

    def after(self, snapshot: dict[str, int], ticks: int) -> None:
        """The clocks ``ticks`` steady ticks after ``snapshot`` (see :meth:`steady`)."""
        moving = self.state.gamerules.daylight_cycle
        for clock, start in snapshot.items():
            self._set(clock, start + (ticks if moving and not self.instances[clock].paused else 0))
