"""The backend protocol: what the runtime needs from an executor of compiled or parsed functions.

Two backends implement it: the numba VM (:class:`emulator.vm.backend.NumbaBackend`, driving
:mod:`emulator.vm.loop`) and the plain-Python reference (:mod:`emulator.reference`);
:func:`emulator.runtime.factory.make_backend` makes either by name. The runtime
(:mod:`emulator.runtime.server`) owns the tick loop and the schedule queue's timing; it asks the backend
to run one *root sequence* at a time. Both act on the same :class:`~emulator.world.state.WorldState`.

Beyond the protocol, a backend may offer what the profiler (:mod:`emulator.profile`) reads:

- :class:`CallRecording`: ``record_calls(recorder, tracer)`` reports every call and every quota
  unit with its call stack to a :class:`CallRecorder`, and each command to a :class:`Tracer` (the
  game's ``/debug function`` events). The reference backend records them.
- :class:`InstructionCounts`: cost per instruction and function, calls, and the host ops Python
  ran for the VM. The numba backend counts them.

And what the runtime uses when it can:

- :class:`TickBatches`: ``run_ticks`` runs the tick functions of many ticks in one go, where
  nothing between them needs the runtime (the numba backend, without leaving the VM).

Command cost — THE rule (both backends must count identically)
==============================================================
From the game's ExecutionContext / BuildContexts / ExecuteCommand / CallFunction (1.20.3+):

Each root sequence starts with ``quota = gamerules.max_command_chain_length``. Work is a queue
of *entries*; before each entry the game checks ``quota <= 0`` and, if so, drops the rest of the
root (and logs "Command execution stopped due to limit (executed N commands)", N = the limit).
Costs are charged as follows:

1. ``CallFunction`` (entering a function: the root itself, ``function f``, each member of a
   tag, each function of ``execute if function``): an entry; costs 1.
2. A command line starts as one entry (BuildContexts). Inside it, each execute stage that has a
   redirect/fork modifier (``as at positioned rotated facing anchored align in on summon``,
   ``if|unless`` *followed by more stages*, ``store ...``) costs 1, once per stage, whatever the
   number of contexts (0 included); these are charged without further checks, so the quota can go
   negative. ``run`` costs nothing. If a stage leaves 0 contexts, later stages are still charged.
   A stage's error (e.g. ``store ... score @s`` run by the server) fails the whole command, and
   the later stages are not charged, unless the chain is forked by then (a ``fork`` stage at or
   before it: ``if|unless ...``, ``as``, ``at``, ``positioned as``, ``rotated as``,
   ``facing entity``, ``on``, ``summon``): then only that context is dropped.
3. The final command then runs once per remaining context, each run its own entry costing 1
   (ExecuteCommand). A condition that ends the chain (``execute if score ...`` without ``run``)
   is such a final command: 1 per context.
4. Commands with custom executors cost nothing themselves: ``function ...`` (only its
   CallFunction entries cost), ``return N``, ``return fail``. ``return run CMD`` costs nothing
   itself; CMD is a new entry costed by rules 2-3. ``execute ... if function F`` is a custom
   modifier: the stage costs nothing, F's calls cost by rule 1, and the rest of the chain is a
   new entry (checked) costed by rules 2-3. If the tag named by ``if function`` is empty, the
   rest of the chain does not run at all.
5. Failing commands cost what they were charged before failing (a failing ``scoreboard`` command
   still costs 1 per context).

So ``scoreboard players set #a o 1`` costs 1; ``execute as @a at @s run say hi`` with 3 players
costs 2 + 3; ``function f`` where f has 4 plain commands costs 1 + 4; a root calling nothing
but ``return 1`` costs 1 (its own CallFunction).

Fork limit: a stage whose produced contexts would reach ``maxCommandForkCount`` (``>=``) fails
the command ("Command execution would fork too many times").

Where the quota stops a root, the backend calls :func:`report_quota_cut`, so the log and the
diagnostic read the same in both backends.
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, NamedTuple, Protocol, runtime_checkable

from emulator.world.context import Context
from emulator.world.records import Frame
from emulator.world.state import WorldState

if TYPE_CHECKING:
    import numpy as np

    from mcfunction_parser import ast
    from mcfunction_parser.nbt import Compound


@dataclass(slots=True)  # not frozen: made for every root, and a frozen one costs three times as much
class RootResult:
    """What running one root sequence did.

    ``cost``: quota units consumed (the "commands executed" the runtime reports per tick; never
    more than the quota plus one command's stage charges). ``result``: the function's return value
    (None when it never returned; 0 for ``return fail``). ``cut``: the quota stopped it.
    """

    cost: int
    result: int | None
    cut: bool = False
    succeeded: bool | None = None  # with a result: whether it was a success (``return fail``, a failed ``return run``: no)


class Backend(Protocol):
    """An executor of functions on a :class:`WorldState`."""

    name: str

    def load(self, packs, state: WorldState, sanitize: bool = False) -> None:
        """Prepare to run ``packs`` (a ``mcfunction_parser.pack.loader.LoadedPacks``) against ``state``.

        With ``sanitize``, every arithmetic result that wraps int32 is appended to
        ``state.overflows`` (the stored value stays the game's).
        """

    def new_world(self, state: WorldState) -> None:
        """Run the packs already loaded against ``state``, a fresh world whose scoreboard and
        entity table intern the names of the last one (``Emulator.new_world``): what the backend
        made of the packs is kept, its per-world counts start again."""

    def run_root(self, function_id: str, context: Context | None = None, arguments: "Compound | None" = None) -> RootResult:
        """Run one root sequence: call ``function_id`` (not a tag; the runtime expands tags) with
        a fresh quota, as ``context`` (None: the server at world spawn), with macro ``arguments``.

        Never raises for anything a pack can do: runtime problems become
        ``state.diagnostics`` (with a function traceback) and the run continues as the game would.
        An unknown ``function_id`` is a diagnostic and a zero-cost result.
        """

    def line_counts(self) -> dict[tuple[str, int], int]:
        """Cost charged so far per ``(source path, line)``, cumulative over the run: the sum over
        all lines equals the total cost minus the roots' own CallFunction charges (a root call is
        on no line). May be ``{}`` if not tracked."""


@dataclass(frozen=True, slots=True)
class TickBatch:
    """What :meth:`TickBatches.run_ticks` ran: each root's cost in order (int64), and whether the
    last one was cut (no other was; none returns a result the runtime reads)."""

    costs: "np.ndarray"
    cut: bool


@runtime_checkable
class TickBatches(Protocol):
    def run_ticks(self, functions: list[str], ticks: int, at_tick: Callable[[int], None]) -> TickBatch | None:
        """Run ``functions`` (the tick functions) each as its own root as :meth:`Backend.run_root`
        would, in order, once per tick for up to ``ticks`` ticks, without coming back in between:
        the runtime has checked that nothing between these ticks needs it (their ends change
        nothing but the clocks). The last tick may be partial: the batch ends with a root after
        which Python was needed (e.g. one that ran a host op or was cut). None when the backend
        cannot run them so. ``at_tick(t)`` is called before anything of tick ``t`` of the batch
        runs in Python (the clocks must read it)."""


# ---------------------------------------------------------------------- what the profiler reads
class CallRecorder(Protocol):
    """Told of each function call a command makes and of each quota unit, as it is charged."""

    def call(self, function_id: str) -> None:
        """A command (``function``, ``execute if function``) called ``function_id``; a root's own
        call is not one (the runtime's root listeners see the roots)."""

    def charge(self, stack: tuple[str, ...]) -> None:
        """One quota unit, charged in ``stack`` (the functions from the root to the one whose
        command was charged; a root's own call is charged as ``(root,)``)."""


class Tracer(Protocol):
    """The game's ``/debug function`` events (DebugCommand.Tracer); ``depth`` is the call depth."""

    def root(self, function_id: str) -> None: ...

    def call(self, depth: int, function_id: str, size: int) -> None: ...

    def command(self, depth: int, text: str) -> None: ...

    def result(self, depth: int, text: str, value: int) -> None: ...

    def error(self, message: str) -> None: ...


@runtime_checkable
class CallRecording(Protocol):
    def record_calls(self, recorder: CallRecorder, tracer: Tracer | None = None) -> None:
        """Report to ``recorder`` (and each command to ``tracer``) from the next :meth:`Backend.load` on."""


class HostRun(NamedTuple):
    """A host op Python ran for the VM: the function (a macro instance's own id), the node, the
    opcode that handed it over (a final command, an execute stage or a store) and the runs."""

    function: str
    node: "ast.Command | ast.Subcommand"
    opcode: int
    runs: int


@runtime_checkable
class InstructionCounts(Protocol):
    """What a bytecode backend counts, cumulative since load (function ids are the compiled
    ones: a macro instance is ``ns:f#N``)."""

    def function_totals(self) -> dict[str, int]:
        """Inclusive cost per function (callees included, outermost activations only)."""

    def call_counts(self) -> dict[str, int]:
        """Calls per function made by commands (roots not included)."""

    def instruction_counts(self) -> dict[tuple[str, int], list[tuple[int, int]]]:
        """Per ``(source path, line)``, ``(opcode, cost charged)`` of each instruction there, in code order."""

    def host_ops_run(self) -> list[HostRun]:
        """Every host op Python ran, in code order."""


def quota_cut_message(limit: int) -> str:
    """The game's log line when the quota stops a root."""
    return f"Command execution stopped due to limit (executed {limit} commands)"


def report_quota_cut(state: WorldState, limit: int, frames: tuple[Frame, ...]) -> None:
    """Log the cut and record a diagnostic saying where (``frames[-1]``: the entry not run)."""
    loc = frames[-1].loc if frames else None
    state.emit("info", quota_cut_message(limit), loc)
    state.error(quota_cut_message(limit), frames, severity="warning")
