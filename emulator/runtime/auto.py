"""The ``auto`` backend: a run starts on the reference backend and moves to the VM once it proves long.

A short run (a pack checked once, a few ticks) spends less time in the reference backend than the
VM takes to start (importing numba and loading or compiling its loop: about 0.3 s warm, seconds
with an empty cache). :class:`AutoBackend` runs the roots on the first backend until they have cost
``switch_after`` (:data:`SWITCH_AFTER`) in all, then loads the second on the same packs and world and runs every
later root there.

Both backends act on the one :class:`~emulator.world.state.WorldState` and keep nothing of the
world between roots (the VM writes its storage numbers back when it stops), so the switch happens
between two roots, never inside one: the run gives what either backend alone gives whatever the
switch point (``tests/backends/test_differential.py`` fuzzes it). The second backend compiles the
packs when it loads, interning their names into the world then instead of before the first root:
the one thing that can tell the runs apart is the order ``*`` names the score holders in where that
order shows (a sanitizer's overflow list), which is the score map's hash order in the game and
differs between the two backends already.
"""
from __future__ import annotations

from collections import Counter
from collections.abc import Callable

from emulator.runtime.backend import Backend, RootResult, TickBatch
from emulator.world.context import Context
from emulator.world.state import WorldState

# The work run on the first backend before the switch, in commands (quota units) plus ROOT_WORK per
# root: the reference backend runs about 120 k scoreboard commands a CPU second, and a root (a
# one-command tick function: its tick, the runtime's steps, the root's own call) costs about what three
# commands cost. So the switch comes after about 0.1 s, under the 0.3 s a warm VM takes to start.
SWITCH_AFTER = 10_000
ROOT_WORK = 3


class AutoBackend:
    """Implements :class:`emulator.runtime.backend.Backend` and
    :class:`~emulator.runtime.backend.TickBatches` (once switched: the second backend's)."""

    name = "auto"

    def __init__(self, first: Backend, later: Callable[[], Backend], switch_after: int = SWITCH_AFTER) -> None:
        self.current = first
        self.later = later
        self.switch_after = switch_after
        self.spent = 0  # work run on the first backend (commands, ROOT_WORK per root)
        self.switched_at: tuple[int, int] | None = None  # (the world's tick, the work run) at the switch
        self._first_lines: dict[tuple[str, int], int] = {}

    @property
    def ran(self) -> str:
        """Which backends ran: ``python``, or ``python, then numba from tick T (after N of work)``."""
        if self.switched_at is None:
            return self.current.name
        tick, spent = self.switched_at
        return f"{self._first_name}, then {self.current.name} from tick {tick} (after {spent:,} of work)"

    def load(self, packs, state: WorldState, sanitize: bool = False) -> None:
        self.packs, self.state, self.sanitize = packs, state, sanitize
        self.current.load(packs, state, sanitize)

    def new_world(self, state: WorldState) -> None:
        self.state = state
        self.current.new_world(state)

    def run_root(self, function_id: str, context: Context | None = None, arguments=None) -> RootResult:
        result = self.current.run_root(function_id, context, arguments)
        if self.switched_at is None:
            self.spent += result.cost + ROOT_WORK
            if self.spent >= self.switch_after:
                self._switch()
        return result

    def run_ticks(self, functions: list[str], ticks: int, at_tick) -> TickBatch | None:
        run_ticks = getattr(self.current, "run_ticks", None)
        return None if self.switched_at is None or run_ticks is None else run_ticks(functions, ticks, at_tick)

    def line_counts(self) -> dict[tuple[str, int], int]:
        return dict(Counter(self._first_lines) + Counter(self.current.line_counts()))

    def _switch(self) -> None:
        """Between two roots: the second backend takes the packs and the world as they are now."""
        self._first_lines = self.current.line_counts()
        self._first_name = self.current.name
        self.current = self.later()
        self.current.load(self.packs, self.state, self.sanitize)
        self.switched_at = (self.state.tick, self.spent)
