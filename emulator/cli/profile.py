"""``dpemu profile``: run packs like ``dpemu run`` and report exact command counts: per tick, per
root (quota headroom), per function (self, total, calls), per line (with the VM's instructions,
i.e. each execute stage), the commands run host-side, and call stacks.

Collapsed stacks and the ``/debug function`` trace need the call stack of every charge, which the
reference backend records (:mod:`emulator.profile.stacks`); those formats run on it.
"""
from __future__ import annotations

import json
import sys
from collections import Counter, defaultdict
from pathlib import Path

import click

from emulator.profile import formats
from emulator.api import Emulator
from emulator.cli.options import OrderedCommand, apply_setup, parse_call, parse_set, parse_until, run_options
from emulator.profile.stacks import StackBackend

STACK_FORMATS = ("collapsed", "trace")


class RootLog:
    """Records every root sequence the runtime runs: (function, cost, cut)."""

    def __init__(self, runtime) -> None:
        self.runs: list[tuple[str, int, bool]] = []
        inner = runtime.run_root

        def run_root(function_id, context=None, arguments=None):
            result = inner(function_id, context, arguments)
            self.runs.append((function_id, result.cost, result.cut))
            return result

        runtime.run_root = run_root

    def summary(self, limit: int) -> list[dict]:
        by_function: dict[str, list[tuple[int, bool]]] = defaultdict(list)
        for function, cost, cut in self.runs:
            by_function[function].append((cost, cut))
        rows = []
        for function, runs in by_function.items():
            costs = [c for c, _ in runs]
            rows.append({"function": function, "runs": len(runs), "max_cost": max(costs),
                         "mean_cost": sum(costs) / len(costs), "headroom": limit - max(costs),
                         "cut": sum(cut for _, cut in runs)})
        return sorted(rows, key=lambda r: -r["max_cost"])


@click.command("profile", cls=OrderedCommand)
@run_options
@click.option("--backend", type=click.Choice(["numba", "python"]),
              help="Default: numba; python for --format collapsed|trace (which need call stacks).")
@click.option("--mc", "mc_version", metavar="VERSION", help="Game version to emulate (default: the packs').")
@click.option("--format", "fmt", type=click.Choice(formats.FORMATS), default="table", show_default=True)
@click.option("--top", default=20, show_default=True, type=click.IntRange(min=1), help="Rows per table section.")
@click.option("-o", "--output", metavar="FILE", type=click.Path(dir_okay=False), help="Write here instead of stdout.")
@click.option("--baseline", metavar="FILE", help="A JSON profile to compare with: exit 1 when a function grew.")
@click.option("--threshold", default=formats.DEFAULT_THRESHOLD, show_default=True, type=click.FloatRange(min=0),
              metavar="PCT", help="Allowed growth per function with --baseline, in percent.")
def profile(packs, ticks, call, set_, until, backend, mc_version, fmt, top, output, baseline, threshold) -> None:
    """Profile PACKS: run #minecraft:load, apply --set and --call in order, run --ticks ticks, report
    command counts."""
    if fmt in STACK_FORMATS and backend == "numba":
        raise click.UsageError(f"--format {fmt} needs call stacks, which only --backend python records")
    saved = _read_baseline(baseline) if baseline else None
    sets, calls = [parse_set(s) for s in set_], [parse_call(c) for c in call]
    stop = parse_until(until) if until else None
    trace = formats.TraceWriter() if fmt == "trace" else None
    emu = _loaded(packs, mc_version, fmt in STACK_FORMATS or backend == "python", trace)
    roots = RootLog(emu.runtime)
    load_commands = emu.start()
    if hasattr(emu.backend, "host_runs"):
        emu.backend.host_runs.clear()  # list what --set/--call and the ticks hand to Python, not the load's setup
    apply_setup(emu, click.get_current_context().meta.get("dpemu.run.order", []), sets, calls)
    for _ in range(ticks):
        emu.tick()
        if stop and stop.met(emu):
            break
    report = build_report(emu, roots, load_commands)
    text = {"table": lambda: formats.write_table(report, top), "json": lambda: formats.write_json(report),
            "collapsed": lambda: formats.write_collapsed(report), "trace": lambda: trace.text()}[fmt]()
    if output:
        Path(output).write_text(text)
    else:
        click.echo(text, nl=False)
    if saved is not None:
        _check_baseline(saved, report, threshold, baseline)


def _loaded(packs, mc_version: str | None, stacks: bool, trace) -> Emulator:
    """An emulator with ``packs`` loaded: the numba VM, or the reference backend recording stacks."""
    emu = Emulator(backend="python" if stacks else "numba")
    if stacks:
        emu.backend = StackBackend(trace)
    try:
        emu.load(list(packs), mc_version)
    except ValueError as error:
        raise click.BadParameter(str(error), param_hint="--mc") from None
    for diag in emu.load_diagnostics:
        if diag.severity == "error":
            click.echo(diag.format(), err=True)
    return emu


def _check_baseline(saved: dict, report: dict, threshold: float, path: str) -> None:
    grown = formats.compare(saved, report, threshold)
    for line in grown:
        click.echo(f"regression: {line}", err=True)
    if grown:
        sys.exit(1)
    click.echo(f"no function grew more than {threshold:g}% over {path}", err=True)


def _read_baseline(path: str) -> dict:
    try:
        data = json.loads(Path(path).read_text())
    except FileNotFoundError:
        raise click.BadParameter(f"{path}: no such file (write one with --format json -o FILE)",
                                 param_hint="--baseline") from None
    except (OSError, ValueError) as error:
        raise click.BadParameter(f"{path}: not a JSON profile ({error})", param_hint="--baseline") from None
    if not isinstance(data, dict) or not isinstance(data.get("functions"), list):
        raise click.BadParameter(f"{path}: not a JSON profile (no \"functions\" list)", param_hint="--baseline")
    return data


# ---------------------------------------------------------------------- the report
def build_report(emu: Emulator, roots: RootLog, load_commands: int = 0) -> dict:
    """The profile; ``load_commands`` of the commands outside ticks were the load functions' (the
    rest were --set/--call's)."""
    runtime = emu.runtime
    series = emu.commands_per_tick
    limit = emu.state.gamerules.max_command_chain_length
    prof = emu.profile
    sources = emu.packs.sources
    backend = emu.backend
    if isinstance(backend, StackBackend):
        stacks = dict(backend.stacks)
        calls = dict(backend.calls)
        totals = _totals_from_stacks(stacks, backend.root_calls)
        instructions: dict = {}
        host = None  # the reference backend runs everything in Python: no VM/host split
    else:
        stacks = None
        calls = _vm_calls(backend, roots)
        totals = prof.functions_total
        instructions = _vm_instructions(backend)
        host = _vm_host(backend, sources)
    names = set(prof.functions_self) | set(totals) | set(calls)
    functions = [{"function": f, "self": prof.functions_self.get(f, 0), "total": totals.get(f),
                  "calls": calls.get(f)} for f in names]
    functions.sort(key=lambda f: (-(f["total"] if f["total"] is not None else f["self"]), f["function"]))
    report = {
        "backend": emu.backend_name,
        "limit": limit,
        "commands": sum(series) + runtime.commands_outside_ticks,
        "outside_ticks": {"load": load_commands, "setup": runtime.commands_outside_ticks - load_commands},
        "ticks": {"count": len(series), "mean": sum(series) / len(series) if series else 0.0,
                  "max": max(series, default=0), "series": series},
        "roots": roots.summary(limit),
        "functions": functions,
        "lines": [{"path": path, "line": line, "commands": count, "source": _source(sources, path, line),
                   "instructions": instructions.get((path, line), [])}
                  for (path, line), count in sorted(prof.lines.items(), key=lambda kv: (-kv[1], kv[0]))],
        "host": host,
    }
    if stacks is not None:
        report["stacks"] = {";".join(stack): count for stack, count in sorted(stacks.items())}
    return report


def _source(sources: dict, path: str, line: int) -> str:
    lines = sources.get(path) or []
    return lines[line - 1].strip() if 0 < line <= len(lines) else ""


def _totals_from_stacks(stacks: dict, root_calls: Counter) -> dict[str, int]:
    """Inclusive cost as the VM counts it (emulator.profile.data): every charge counts once for
    each distinct function on its stack, except a root's own call, which is on no line."""
    totals: Counter = Counter()
    for stack, count in stacks.items():
        for function in set(stack):
            totals[function] += count
    totals.subtract(root_calls)
    return {f: c for f, c in totals.items() if c}


def _vm_instructions(backend) -> dict[tuple[str, int], list[dict]]:
    """Per source line, the cost charged at each VM instruction (an execute stage, the final
    command, a call), in code order."""
    import numpy as np

    from emulator.vm.opcodes import BY_CODE

    rows = backend.program.rows
    out: dict[tuple[str, int], list[dict]] = defaultdict(list)
    for pc in np.flatnonzero(backend.counts):
        loc = backend.program.locs[pc]
        if loc is not None:
            out[(loc.path, loc.line)].append({"op": BY_CODE[rows[pc][0]].name,
                                              "count": int(backend.counts[pc])})
    return dict(out)


def _vm_calls(backend, roots: RootLog) -> dict[str, int]:
    """Calls per function: the cost at each ``function`` instruction (1 per call) plus root runs."""
    import numpy as np

    from emulator.vm import loop as vm
    from emulator.profile.data import base_function

    rows = backend.program.rows
    calls: Counter = Counter(function for function, cost, _ in roots.runs if cost)
    for pc in np.flatnonzero(backend.counts):
        if rows[pc][0] == vm.OP_CALL:
            calls[base_function(backend.program.functions[rows[pc][1]])] += int(backend.counts[pc])
    return dict(calls)


# what each host opcode hands to Python, as the profile names it
HOST_KINDS = {"HOST": "command", "HOSTSTAGE": "stage", "HOSTSTORE": "store"}


def _vm_host(backend, sources: dict) -> list[dict]:
    """The host ops Python ran after the load (final commands, execute stages, stores) with how
    often each ran, macro instances of a line counted together. Read from the backend's record of
    the ops it served, not from the VM's charged counts: a store is never charged, so the counts
    would hide a host-run store."""
    from emulator.profile.data import base_function
    from emulator.vm.opcodes import BY_CODE

    code = backend.program.rows
    runs: Counter = Counter()
    for pc, count in backend.host_runs.items():
        host_op = backend.program.host_ops[code[pc][1]]
        loc = host_op.node.loc
        runs[(base_function(host_op.function), loc.path, loc.line, HOST_KINDS[BY_CODE[code[pc][0]].name])] += count
    rows = [{"function": function, "path": path, "line": line, "op": op, "command": _source(sources, path, line),
             "count": count} for (function, path, line, op), count in runs.items()]
    return sorted(rows, key=lambda r: (-r["count"], r["path"], r["line"]))
