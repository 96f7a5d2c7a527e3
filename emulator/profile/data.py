"""A run's profile: exact command counts per tick, root, function, source line, VM instruction and
host op, and the call stacks, read from the runtime's root listeners and what the backend counts
(:mod:`emulator.runtime.backend`: ``line_counts``, :class:`InstructionCounts`, :class:`CallRecording`).

``self`` of a function is the cost charged by its own commands (a ``function`` call's own charge
belongs to the calling line; a root's own call is on no line); ``total`` adds its callees,
counted once per outermost activation (the numba backend counts it, the python backend when it
records call stacks). Macro instances (``ns:f#3``) fold into their function.
"""
from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field

from emulator.profile.stacks import CallStacks
from emulator.runtime.backend import InstructionCounts, RootResult
from emulator.runtime.server import Runtime


@dataclass
class RootRuns:
    """One function's runs as a root sequence."""

    runs: int = 0
    called: int = 0  # runs that made the root's own call (charged 1, on no line)
    cost: int = 0
    max_cost: int = 0
    cuts: int = 0


class RootStats:
    """A root listener (:attr:`emulator.runtime.server.Runtime.root_listeners`): the runs per function."""

    def __init__(self) -> None:
        self.by_function: dict[str, RootRuns] = {}

    def __call__(self, function_id: str, result: RootResult) -> None:  # every root: kept cheap
        runs = self.by_function.get(function_id)
        if runs is None:
            runs = self.by_function[function_id] = RootRuns()
        runs.runs += 1
        cost = result.cost
        if cost > 0:
            runs.called += 1
            runs.cost += cost
            if cost > runs.max_cost:
                runs.max_cost = cost
        if result.cut:
            runs.cuts += 1

    def roots_ran(self, function_id: str, costs) -> None:
        """Many runs of one root at once (numpy costs; none was cut)."""
        runs = self.by_function.setdefault(function_id, RootRuns())
        runs.runs += len(costs)
        runs.called += int((costs > 0).sum())
        runs.cost += int(costs.sum())
        runs.max_cost = max(runs.max_cost, int(costs.max()))

    def calls(self) -> Counter:
        return Counter({f: r.called for f, r in self.by_function.items() if r.called})


@dataclass
class Profile:
    lines: dict[tuple[str, int], int] = field(default_factory=dict)  # (path, line) -> commands
    functions_self: dict[str, int] = field(default_factory=dict)
    functions_total: dict[str, int] = field(default_factory=dict)  # {} when not counted
    ticks: list[int] = field(default_factory=list)  # commands per tick
    backend: str = ""
    limit: int = 0  # each root's quota (maxCommandChainLength)
    outside_ticks: int = 0  # commands run between ticks (the load when started, calls)
    roots: dict[str, RootRuns] = field(default_factory=dict)
    calls: dict[str, int] = field(default_factory=dict)  # calls per function, roots included; {} when not counted
    # (path, line) -> (opcode, commands) per VM instruction there, in code order
    instructions: dict[tuple[str, int], list[tuple[int, int]]] = field(default_factory=dict)
    # (function, path, line, opcode) -> runs of each host op; None when the backend runs every command in Python
    host: dict[tuple[str, str, int, int], int] | None = None
    stacks: dict[tuple[str, ...], int] | None = None  # commands per call stack (root first), when recorded

    def top_lines(self, n: int = 20) -> list[tuple[tuple[str, int], int]]:
        return sorted(self.lines.items(), key=lambda kv: -kv[1])[:n]

    def to_json(self) -> dict:
        return {
            "lines": [{"path": p, "line": line, "commands": c} for (p, line), c in self.top_lines(len(self.lines))],
            "functions": [
                {"function": f, "self": c, "total": self.functions_total.get(f)}
                for f, c in sorted(self.functions_self.items(), key=lambda kv: -kv[1])
            ],
            "ticks": self.ticks,
        }


def base_function(function_id: str) -> str:
    return function_id.split("#", 1)[0]


class Profiler:
    """The profile of everything ``runtime`` runs from now on: it listens to the roots and reads
    the backend's counters; ``stacks`` is the recorder the backend reports its calls to (if any)."""

    def __init__(self, runtime: Runtime, stacks: CallStacks | None = None) -> None:
        self.runtime = runtime
        self.stacks = stacks
        self.roots = RootStats()
        runtime.root_listeners.append(self.roots)
        self.earlier = _Counts()  # what the backend counted before a reload gave it new packs
        runtime.reload_listeners.append(self._keep_counts)

    def _keep_counts(self) -> None:
        self.earlier = self.earlier.plus(_Counts.of(self.runtime.backend, self.runtime.packs))

    def profile(self) -> Profile:
        runtime, backend, roots = self.runtime, self.runtime.backend, self.roots
        counts = self.earlier.plus(_Counts.of(backend, runtime.packs))
        profile = Profile(dict(counts.lines), _self_costs(counts.lines, counts.function_of),
                          ticks=list(runtime.commands_per_tick),
                          backend=backend.name, limit=runtime.state.gamerules.max_command_chain_length,
                          outside_ticks=runtime.commands_outside_ticks, roots=dict(roots.by_function))
        if isinstance(backend, InstructionCounts):
            profile.functions_total = counts.totals
            profile.calls = dict(counts.calls + roots.calls())
            profile.instructions = counts.instructions
            profile.host = dict(counts.host)
        elif self.stacks is not None:
            profile.functions_total = self.stacks.totals(roots.calls())
            profile.calls = dict(self.stacks.calls + roots.calls())
            profile.stacks = dict(self.stacks.stacks)
        return profile


@dataclass
class _Counts:
    """A backend's counters read at once, and the function of each source path then."""

    lines: Counter = field(default_factory=Counter)
    function_of: dict[str, str] = field(default_factory=dict)
    totals: Counter = field(default_factory=Counter)
    calls: Counter = field(default_factory=Counter)
    instructions: dict = field(default_factory=dict)
    host: Counter = field(default_factory=Counter)

    @classmethod
    def of(cls, backend, packs) -> "_Counts":
        counts = cls(Counter(backend.line_counts()), {f.path: fid for fid, f in packs.functions.items()})
        if isinstance(backend, InstructionCounts):
            counts.totals = _folded(backend.function_totals())
            counts.calls = _folded(backend.call_counts())
            counts.instructions = backend.instruction_counts()
            counts.host = Counter(_host_runs(backend))
        return counts

    def plus(self, later: "_Counts") -> "_Counts":
        if not self.function_of:  # nothing counted before
            return later
        instructions = dict(self.instructions)
        for line, ops in later.instructions.items():
            before = instructions.get(line, [])
            same = [op for op, _ in before] == [op for op, _ in ops]
            instructions[line] = [(op, a + b) for (op, a), (_, b) in zip(before, ops)] if same else before + ops
        return _Counts(self.lines + later.lines, {**self.function_of, **later.function_of}, self.totals + later.totals,
                       self.calls + later.calls, instructions, self.host + later.host)


def _self_costs(lines: dict[tuple[str, int], int], function_of: dict[str, str]) -> dict[str, int]:
    costs: Counter = Counter()
    for (path, _line), count in lines.items():
        costs[function_of.get(path, path)] += count
    return dict(costs)


def _folded(counts: dict[str, int]) -> Counter:
    out: Counter = Counter()
    for function, count in counts.items():
        out[base_function(function)] += count
    return out


def _host_runs(backend: InstructionCounts) -> dict[tuple[str, str, int, int], int]:
    """Runs per host op, the instances of a macro line counted together."""
    out: Counter = Counter()
    for run in backend.host_ops_run():
        loc = run.node.loc
        out[(base_function(run.function), loc.path, loc.line, run.opcode)] += run.runs
    return dict(out)
