"""The Python API: ``Emulator``, the front door over the runtime (:mod:`emulator.runtime.server`),
which runs the ticks on a backend. It loads packs, calls functions, runs ticks and reports.

    emu = Emulator()                    # or Emulator(backend="python"), Emulator(sanitize=True)
    emu.load("path/to/pack")
    emu.set_score("#n", "input", 10)
    emu.call("pool:setup")
    emu.tick(20)
    emu.score("#ball", "x")             # None when unset
    emu.profile                         # command counts per tick, root, function, line
"""
from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import replace
from pathlib import Path

from emulator.commands import entities as world_entities
from emulator.profile.data import Profile, Profiler
from emulator.profile.stacks import CallStacks
from emulator.runtime.backend import Backend, CallRecording, RootResult, Tracer
from emulator.runtime.factory import make_backend
from emulator.runtime.server import Runtime
from emulator.world import players
from emulator.world.clocks import WorldClocks
from emulator.world.context import Context
from emulator.world.semantics import INT_MAX, INT_MIN
from mcfunction_parser.diagnostics import Diagnostic


class Emulator:
    def __init__(self, backend: str | Backend = "numba", sanitize: bool = False, shuffle: int | None = None,
                 stacks: bool = False, trace: Tracer | None = None) -> None:
        """``backend``: ``"numba"`` (the VM), ``"python"`` (the reference) or a backend object
        (:class:`emulator.runtime.backend.Backend`). ``stacks``: record the call stack of every
        command (``profile.stacks``); ``trace``: report every call and command to this tracer
        (e.g. :class:`emulator.profile.formats.TraceWriter`, the game's ``/debug function``
        trace). Both need a backend that records calls: the python one."""
        self.backend = make_backend(backend) if isinstance(backend, str) else backend
        self.backend_name = self.backend.name
        self.sanitize = sanitize
        self.shuffle = shuffle  # seed permuting unsorted @e order (None: creation order)
        self.records_calls = stacks or trace is not None
        if self.records_calls and not isinstance(self.backend, CallRecording):
            raise ValueError(f"the {self.backend_name} backend records no call stacks; the python backend does")
        self.trace = trace
        self.state = world_entities.new_state(shuffle)
        self.packs = None
        self.runtime: Runtime | None = None
        self.profiler: Profiler | None = None

    # ------------------------------------------------------------------ loading
    def load(self, paths: str | Path | Sequence[str | Path], mc_version: str | None = None,
             game_jar: str | Path | None = None):
        """Load one pack or several (later ones override), over the game's vanilla tags and loot
        tables when ``game_jar`` names its jar; returns the loaded packs. Pack problems are in
        :attr:`load_diagnostics`; the world starts empty."""
        from mcfunction_parser.pack.loader import load_packs

        if isinstance(paths, (str, Path)):
            paths = [paths]
        return self.load_parsed(load_packs([Path(p) for p in paths], mc_version, game_jar=game_jar))

    def load_parsed(self, packs):
        """Start an empty world on packs already loaded by ``mcfunction_parser.load_packs`` (a test
        runner parses a pack once and starts a fresh world per test); returns ``packs``. The
        profile starts again too."""
        self.packs = packs
        self._start_world(world_entities.new_state(self.shuffle), compiled=False)
        return packs

    def new_world(self) -> None:
        """A fresh world on the packs already loaded, as :meth:`load_parsed` leaves it, without
        compiling them again: many independent runs of one pack (a sweep's shots) share one
        compiled program. The new world interns the names the program was compiled with (score
        holders, objectives, entity tags and types) and nothing else of the old one."""
        runtime = self._runtime()
        if runtime.reloaded:  # the backend runs the packs a reload read: compile the loaded ones again
            self._start_world(world_entities.new_state(self.shuffle), compiled=False)
            return
        old = runtime.state
        state = world_entities.new_state(self.shuffle)
        state.scoreboard.intern_names_of(old.scoreboard)
        state.entities.table.intern_names_of(old.entities.table)
        self._start_world(state, compiled=True)

    def _start_world(self, state, compiled: bool) -> None:
        state.version = self.packs.version
        if self.packs.clocks is not None:
            state.clocks = WorldClocks(state, self.packs.clocks)
        self.state = state
        stacks = CallStacks() if self.records_calls else None
        if stacks is not None:
            self.backend.record_calls(stacks, self.trace)
        self.runtime = Runtime(self.backend, self.packs, state, self.sanitize, compiled)
        self.profiler = Profiler(self.runtime, stacks)

    @property
    def load_diagnostics(self) -> list[Diagnostic]:
        return list(self.packs.diagnostics) if self.packs else []

    @property
    def backend_ran(self) -> str:
        """Which backend ran the packs: its name, or for ``auto`` which ran and where it switched
        (``python, then numba from tick 3 (after 10,002 of work)``)."""
        return getattr(self.backend, "ran", self.backend_name)

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
        return self._runtime().start()

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
        """Run ``n`` server ticks (:meth:`emulator.runtime.server.Runtime.run_ticks`: on the numba
        backend, quiet ticks run inside the VM without coming back); returns the commands executed."""
        return (self.runtime or self._runtime()).run_ticks(n)

    def run_until(self, predicate: Callable[["Emulator"], bool], max_ticks: int) -> int:
        """Tick until ``predicate(self)`` holds (checked after each tick) or ``max_ticks`` ran;
        returns the ticks run."""
        runtime = self._runtime()
        for n in range(1, max_ticks + 1):
            runtime.tick()
            if predicate(self):
                return n
        return max_ticks

    # ------------------------------------------------------------------ scores
    def score(self, holder: str, objective: str) -> int | None:
        return self.state.scoreboard.get(holder, objective)

    def score_block(self, holders, objectives):
        """Many scores at once: a numpy int64 array [holder, objective], 0 where unset."""
        return self.state.scoreboard.block(holders, objectives)

    def score_reader(self, holders, objectives):
        """A function returning :meth:`score_block` of these holders and objectives as they are
        when called, made for reading them every tick (the names are looked up once)."""
        return self.state.scoreboard.reader(holders, objectives)

    def set_score(self, holder: str, objective: str, value: int) -> None:
        """Set a score (creating the objective as ``dummy`` if needed); value must be an int32."""
        if not INT_MIN <= value <= INT_MAX:
            raise ValueError(f"score {value} is outside the 32-bit range")
        self.state.scoreboard.set(holder, objective, int(value))

    def objectives(self) -> list[str]:
        """The objectives that exist now, in creation order."""
        board = self.state.scoreboard
        return [name for name in board.objectives if board.exists(name)]

    def scores(self) -> dict[str, dict[str, int]]:
        return self.state.scoreboard.scores()

    # ------------------------------------------------------------------ entities
    def add_player(self, name: str, pos=(0.0, 0.0, 0.0), rotation=(0.0, 0.0), gamemode: str | None = None,
                   level: int = 0, on_ground: bool = True, dimension: str = "minecraft:overworld") -> str:
        """A simulated player joins (after :meth:`load`, at any tick; a player of that name already
        online leaves first, as the server disconnects it); returns its UUID string, the offline-mode
        UUID of its name. ``rotation`` is (yaw, pitch) in degrees. Such a player stands for one a
        client drives: the server does not move it (ServerPlayer.tick does not call travel; only
        PackTest's dummies fall, :mod:`emulator.world.falling`), so ``on_ground`` is what its client
        reports: standing (``OnGround:1b``, as a player on a floor does) or in the air; ``dimension`` is
        the level it joins in (the packs' own dimensions once loaded); without a ``gamemode`` it plays
        the world's default (survival, or what ``defaultgamemode`` set). Up to 1.21.3 it takes no
        damage for its first 60 ticks, as every player who joins (:mod:`emulator.world.spawn_protection`).
        See :mod:`emulator.world.players`."""
        if dimension not in self.state.entities.table.levels.ids:
            raise ValueError(f"no dimension {dimension!r} (the vanilla ones and the packs' data/<ns>/dimension/)")
        return players.join(self.state, name, pos, rotation, gamemode, level, on_ground, dimension).uuid_string

    def remove_player(self, name: str) -> None:
        """The player leaves the game (``minecraft.custom:minecraft.leave_game`` + 1; its scores stay)."""
        players.leave(self.state, self._player(name))

    def place_player(self, name: str, pos=None, rotation=None, on_ground: bool | None = None) -> None:
        """Move a player (a dummy too), turn it, or stand it on the ground / lift it into the air."""
        players.place(self._player(name), pos, rotation, on_ground)

    def _player(self, name: str):
        player = players.online(self.state, name)
        if player is None:
            raise ValueError(f"no player named {name!r} is online")
        return player

    def entities(self, selector: str = "@e") -> list[dict]:
        """What ``selector`` (a selector, player name or UUID) finds, run as the server at world
        spawn: one dict per entity (uuid, type, name, tags, pos, rotation, dimension, scores)."""
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
    def commands_outside_ticks(self) -> int:
        """Commands run between ticks: the load functions when :meth:`start` ran them, and calls."""
        return self.runtime.commands_outside_ticks if self.runtime else 0

    @property
    def max_root_cost(self) -> int:
        return self.runtime.max_root_cost if self.runtime else 0

    @property
    def quota(self) -> int:
        """Each root's command budget now (the ``maxCommandChainLength`` gamerule)."""
        return self.state.gamerules.max_command_chain_length

    @property
    def profile(self) -> Profile:
        """Exact command counts of the run since :meth:`load` (:mod:`emulator.profile.data`)."""
        return self.profiler.profile() if self.profiler else Profile(backend=self.backend_name)


def _normalise(function: str) -> str:
    tag = function.startswith("#")
    name = function[1:] if tag else function
    if ":" not in name:
        name = "minecraft:" + name
    return ("#" if tag else "") + name


__all__ = ["Emulator", "RootResult"]
