"""The Python API: ``Emulator`` loads packs, calls functions, runs ticks and reports.

    emu = Emulator()                    # or Emulator(backend="python"), Emulator(sanitize=True)
    emu.load("path/to/pack")
    emu.set_score("#n", "input", 10)
    emu.call("pool:setup")
    emu.tick(20)
    emu.score("#ball", "x")             # None when unset
"""
from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import replace
from pathlib import Path

from emulator.runtime.backend import Backend, RootResult
from emulator.profile.data import Profile, fold
from emulator.runtime.server import LOAD_TAG, Runtime
from emulator.world.semantics import INT_MAX, INT_MIN
from emulator.commands import entities as world_entities
from emulator.world import statistics
from emulator.world.state import Context
from mcfunction_parser.diagnostics import Diagnostic


def make_backend(name: str) -> Backend:
    if name == "numba":
        from emulator.vm.backend import NumbaBackend

        return NumbaBackend()
    if name == "python":
        from emulator.reference import ReferenceBackend

        return ReferenceBackend()
    raise ValueError(f"unknown backend {name!r}: expected 'numba' or 'python'")


class Emulator:
    def __init__(self, backend: str = "numba", sanitize: bool = False, shuffle: int | None = None) -> None:
        self.backend_name = backend
        self.sanitize = sanitize
        self.shuffle = shuffle  # seed permuting unsorted @e order (None: creation order)
        self.backend = make_backend(backend)
        self.state = world_entities.new_state(shuffle)
        self.packs = None
        self.runtime: Runtime | None = None

    # ------------------------------------------------------------------ loading
    def load(self, paths: str | Path | Sequence[str | Path], mc_version: str | None = None):
        """Load one pack or several (later ones override); returns the loaded packs. Pack problems
        are in :attr:`load_diagnostics`; the world starts empty."""
        from mcfunction_parser.pack.loader import load_packs

        if isinstance(paths, (str, Path)):
            paths = [paths]
        return self.load_parsed(load_packs([Path(p) for p in paths], mc_version))

    def load_parsed(self, packs):
        """Start an empty world on packs already loaded by ``mcfunction_parser.load_packs`` (a test
        runner parses a pack once and starts a fresh world per test); returns ``packs``."""
        self.packs = packs
        self.state = world_entities.new_state(self.shuffle)
        self.backend.load(packs, self.state, self.sanitize)
        self.runtime = Runtime(self.backend, packs, self.state)
        return packs

    @property
    def load_diagnostics(self) -> list[Diagnostic]:
        return list(self.packs.diagnostics) if self.packs else []

    def _runtime(self) -> Runtime:
        if self.runtime is None:
            raise RuntimeError("no pack loaded: call Emulator.load(path) first")
        return self.runtime

    # ------------------------------------------------------------------ running
    def start(self) -> int:
        """The world loads: run ``#minecraft:load`` now (each member its own root, as the server),
        as the game does when a world (re)loads, before any player command can arrive. Its commands
        count outside the ticks; the next tick runs only ``#minecraft:tick`` and the schedule.
        Without this call the first tick runs the load functions. Returns the commands executed
        (0 when the load functions already ran)."""
        runtime = self._runtime()
        if runtime.loaded:
            return 0
        runtime.loaded = True
        return sum(runtime.call(f).cost for f in runtime.members(LOAD_TAG))

    def call(self, function: str, as_=None, at: tuple[float, float, float] | None = None, arguments=None) -> int | None:
        """Run ``function`` (``ns:path``, ``path`` for ``minecraft:``, or ``#tag``: each member)
        as one root sequence, as the server at ``at`` (default: world spawn), or with ``as_`` (a
        player name, a UUID string or a selector finding one entity) as that entity at its
        position and rotation (``at`` still overrides the position). Returns the function's return
        value (None when it did not return; for a tag, the last member's)."""
        runtime = self._runtime()
        context = Context(pos=tuple(float(c) for c in at)) if at is not None else None
        if as_ is not None:
            context = world_entities.entity_context(self.state, self._one_entity(as_))
            if at is not None:
                context = replace(context, pos=tuple(float(c) for c in at))
        name = _normalise(function)
        if name.startswith("#"):
            results = [runtime.call(f, context, arguments) for f in runtime.members(name[1:])]
            return results[-1].result if results else None
        return runtime.call(name, context, arguments).result

    def tick(self, n: int = 1) -> int:
        """Run ``n`` ticks; returns the commands executed."""
        runtime = self._runtime()
        return sum(self._tick(runtime) for _ in range(n))

    def _tick(self, runtime: Runtime) -> int:
        """One server tick: the functions and schedules, then the players' per-tick statistics."""
        cost = runtime.tick()
        statistics.tick_players(self.state)
        return cost

    def run_until(self, predicate: Callable[["Emulator"], bool], max_ticks: int) -> int:
        """Tick until ``predicate(self)`` holds (checked after each tick) or ``max_ticks`` ran;
        returns the ticks run."""
        runtime = self._runtime()
        for n in range(1, max_ticks + 1):
            self._tick(runtime)
            if predicate(self):
                return n
        return max_ticks

    # ------------------------------------------------------------------ scores
    def score(self, holder: str, objective: str) -> int | None:
        return self.state.scoreboard.get(holder, objective)

    def set_score(self, holder: str, objective: str, value: int) -> None:
        """Set a score (creating the objective as ``dummy`` if needed); value must be an int32."""
        if not INT_MIN <= value <= INT_MAX:
            raise ValueError(f"score {value} is outside the 32-bit range")
        self.state.scoreboard.set(holder, objective, int(value))

    def scores(self) -> dict[str, dict[str, int]]:
        return self.state.scoreboard.scores()

    # ------------------------------------------------------------------ entities
    def add_player(self, name: str, pos=(0.0, 0.0, 0.0), rotation=(0.0, 0.0), gamemode: str = "survival",
                   level: int = 0) -> str:
        """Put a simulated player in the world (after :meth:`load`); returns its UUID string.
        ``rotation`` is (yaw, pitch) in degrees."""
        player = self.state.entities.add_player(name, tuple(float(c) for c in pos), rotation[0], rotation[1],
                                                gamemode, level)
        return player.uuid_string

    def entities(self, selector: str = "@e") -> list[dict]:
        """What ``selector`` (a selector, player name or UUID) finds, run as the server at world
        spawn: one dict per entity (uuid, type, tags, pos, rotation, scores)."""
        return [world_entities.describe(self.state, e) for e in self._select(selector)]

    def _select(self, text: str):
        target = world_entities.parse_target(text)
        return world_entities.select(self.state, target, Context())

    def _one_entity(self, text: str):
        found = self._select(text)
        if len(found) != 1:
            raise ValueError(f"{text!r} finds {len(found)} entities; exactly one is needed")
        return found[0]

    # ------------------------------------------------------------------ reports
    @property
    def log(self):
        return self.state.log

    @property
    def diagnostics(self):
        """Runtime diagnostics (each with a function traceback)."""
        return self.state.diagnostics

    @property
    def overflows(self):
        return self.state.overflows

    @property
    def ticks(self) -> int:
        return self.state.tick

    @property
    def commands_per_tick(self) -> list[int]:
        return list(self.runtime.commands_per_tick) if self.runtime else []

    @property
    def max_root_cost(self) -> int:
        return self.runtime.max_root_cost if self.runtime else 0

    @property
    def profile(self) -> Profile:
        paths = {f.path: fid for fid, f in self.packs.functions.items()} if self.packs else {}
        totals = self.backend.function_totals() if hasattr(self.backend, "function_totals") else None
        return fold(self.backend.line_counts() if self.packs else {}, paths, totals, self.commands_per_tick)


def _normalise(function: str) -> str:
    tag = function.startswith("#")
    name = function[1:] if tag else function
    if ":" not in name:
        name = "minecraft:" + name
    return ("#" if tag else "") + name


__all__ = ["Emulator", "RootResult"]
