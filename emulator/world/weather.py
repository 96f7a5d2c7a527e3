"""The overworld's weather (every level shares its level data; only a level with sky light rains).

- ``Weather``: the saved timers and flags (ServerLevelData clearWeatherTime, rainTime,
  thunderTime, raining, thundering) and the levels the predicates read (Level.rainLevel,
  thunderLevel, float32).
- ``Weather.set(clear, duration, raining, thundering)``: ServerLevel.setWeatherParameters;
  ``reset_cycle()``: ServerLevel.resetWeatherCycle.
- ``Weather.advance(cycle)``: ServerLevel.advanceWeatherCycle, once per tick: with the
  ``doWeatherCycle`` rule the timers count down (a timer at 0 draws a new one; its draw is not the
  game's random), then the rain and thunder levels move 0.01 towards the flags.
  ``advance_ticks(n, cycle)``: the same n times, the quiet stretches (the levels at their flags'
  bound, no timer running out) counted down at once, as the VM's batches of ticks need.
- ``Weather.is_raining(dimension)`` / ``is_thundering(dimension)``: Level.isRaining (rain level >
  0.2) and isThundering (thunder level x rain level > 0.9, in a level with sky light and no ceiling),
  what the ``weather_check`` predicate tests.
"""
from __future__ import annotations

import random
from dataclasses import dataclass, field

import numpy as np

# ServerLevel's IntProviders (UniformInt.of, bounds inclusive)
RAIN_DELAY = (12000, 180000)
RAIN_DURATION = (12000, 24000)
THUNDER_DELAY = (12000, 180000)
THUNDER_DURATION = (3600, 15600)
# the levels whose dimension type has sky light and no ceiling (the vanilla dimension types)
SKY_LEVELS = frozenset({"minecraft:overworld"})

_STEP = np.float32(0.01)


@dataclass
class Weather:
    clear_time: int = 0
    rain_time: int = 0
    thunder_time: int = 0
    raining: bool = False
    thundering: bool = False
    rain_level: np.float32 = np.float32(0.0)
    thunder_level: np.float32 = np.float32(0.0)
    random: random.Random = field(default_factory=lambda: random.Random(0))  # stands for the level's random
    # ticks known to only count the timers down (with the rule as it was then): 0, look again
    _quiet: int = field(default=0, repr=False, compare=False)
    _quiet_cycle: bool = field(default=True, repr=False, compare=False)

    def set(self, clear: int, duration: int, raining: bool, thundering: bool) -> None:
        self.clear_time, self.rain_time, self.thunder_time = clear, duration, duration
        self.raining, self.thundering = raining, thundering
        self._quiet = 0

    def reset_cycle(self) -> None:
        """ServerLevel.resetWeatherCycle: no rain or thunder, their timers 0 (the clear timer kept)."""
        self.rain_time = self.thunder_time = 0
        self.raining = self.thundering = False
        self._quiet = 0

    def sample(self, bounds: tuple[int, int]) -> int:
        return self.random.randint(*bounds)

    def advance(self, cycle: bool) -> None:
        if self._quiet > 0 and self._quiet_cycle == cycle:  # the common tick: straight to the count
            self._count_quiet(1, cycle)
        else:
            self.advance_ticks(1, cycle)

    def advance_ticks(self, n: int, cycle: bool) -> None:
        while n > 0:
            if self._quiet <= 0 or self._quiet_cycle != cycle:
                self._quiet, self._quiet_cycle = self._quiet_ticks(cycle), cycle
            quiet = min(n, self._quiet)
            if quiet > 0:
                self._count_quiet(quiet, cycle)
                n -= quiet
            else:
                self._step(cycle)
                n -= 1

    def _count_quiet(self, quiet: int, cycle: bool) -> None:
        """``quiet`` quiet ticks (:meth:`_quiet_ticks`): whole numbers counted down, no float32 level moved."""
        if cycle and self.clear_time > 0:
            self.clear_time -= quiet
        elif cycle:
            self.rain_time -= quiet
            self.thunder_time -= quiet
        self._quiet -= quiet

    def _step(self, cycle: bool) -> None:
        if cycle:
            self._count_down()
        self.thunder_level = _towards(self.thunder_level, self.thundering)
        self.rain_level = _towards(self.rain_level, self.raining)

    def _quiet_ticks(self, cycle: bool) -> int:
        """How many ticks from now only count the timers down, each as one :meth:`advance` would: the
        levels rest at their flags' bound and no timer runs out (or draws) before the last of them."""
        if self.rain_level != (1 if self.raining else 0) or self.thunder_level != (1 if self.thundering else 0):
            return 0
        if not cycle:
            return 1 << 62
        if self.clear_time > 0:  # steady once the first tick of it cleared the flags and set both timers to 1
            steady = not (self.raining or self.thundering) and self.rain_time == self.thunder_time == 1
            return self.clear_time if steady else 0
        return min(self.rain_time, self.thunder_time) - 1

    def _count_down(self) -> None:
        if self.clear_time > 0:
            self.clear_time -= 1
            self.thunder_time = 0 if self.thundering else 1
            self.rain_time = 0 if self.raining else 1
            self.thundering = self.raining = False
            return
        self.thunder_time, self.thundering = self._timer(self.thunder_time, self.thundering,
                                                         THUNDER_DURATION, THUNDER_DELAY)
        self.rain_time, self.raining = self._timer(self.rain_time, self.raining, RAIN_DURATION, RAIN_DELAY)

    def _timer(self, time: int, on: bool, duration, delay) -> tuple[int, bool]:
        if time > 0:
            time -= 1
            return time, (not on) if time == 0 else on
        return self.sample(duration if on else delay), on

    def is_raining(self, dimension: str) -> bool:
        return dimension in SKY_LEVELS and float(self.rain_level) > 0.2

    def is_thundering(self, dimension: str) -> bool:
        return dimension in SKY_LEVELS and float(np.float32(self.thunder_level * self.rain_level)) > 0.9


def _towards(level: np.float32, on: bool) -> np.float32:
    moved = np.float32(level + _STEP) if on else np.float32(level - _STEP)
    return np.float32(min(max(moved, np.float32(0.0)), np.float32(1.0)))
