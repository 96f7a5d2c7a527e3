"""``dpemu profile``: run packs like ``dpemu run`` and report exact command counts: per tick, per
root (quota headroom), per function (self, total, calls), per line (with the VM's instructions,
i.e. each execute stage), the commands run host-side, and call stacks. The counts are the
emulator's profile (:attr:`emulator.api.Emulator.profile`); this module only writes them out.

Collapsed stacks and the ``/debug function`` trace need the call stack of every charge, which the
reference backend records; those formats run on it.
"""
from __future__ import annotations

import json
import sys
from collections import Counter
from pathlib import Path

import click

from emulator.profile import formats
from emulator.api import Emulator
from emulator.cli.options import (
    OrderedCommand, apply_setup, load_or_usage_error, parse_call, parse_set, parse_until, run_options,
)
from emulator.cli.outcome import exit_status, fail_option, has_errors, interruptible, progress
from emulator.cli.params import OutputPath, write_output
from emulator.profile.data import Profile, RootRuns

STACK_FORMATS = ("collapsed", "trace")


@click.command("profile", cls=OrderedCommand)
@run_options
@click.option("--backend", type=click.Choice(["numba", "python"]),
              help="Default: numba; python for --format collapsed|trace (which need call stacks).")
@click.option("--mc", "mc_version", metavar="VERSION", help="Game version to emulate (default: the packs').")
@click.option("--format", "fmt", type=click.Choice(formats.FORMATS), default="table", show_default=True)
@click.option("--top", default=20, show_default=True, type=click.IntRange(min=1), help="Rows per table section.")
@click.option("-o", "--output", metavar="FILE", type=OutputPath(), help="Write here instead of stdout.")
@click.option("--baseline", metavar="FILE", help="A JSON profile to compare with: exit 1 when a function grew.")
@click.option("--threshold", default=formats.DEFAULT_THRESHOLD, show_default=True, type=click.FloatRange(min=0),
              metavar="PCT", help="Allowed growth per function with --baseline, in percent.")
@fail_option
def profile(packs, ticks, call, set_, until, game_jar, backend, mc_version, fmt, top, output, baseline, threshold,
            no_fail) -> None:
    """Profile PACKS: report exact command counts.

    Runs #minecraft:load, applies --set and --call in order, then runs --ticks ticks."""
    if fmt in STACK_FORMATS and backend == "numba":
        raise click.UsageError(f"--format {fmt} needs call stacks, which only --backend python records")
    saved = _read_baseline(baseline) if baseline else None
    sets, calls = [parse_set(s) for s in set_], [parse_call(c) for c in call]
    stop = parse_until(until) if until else None
    trace = formats.TraceWriter() if fmt == "trace" else None
    emu = _loaded(packs, mc_version, fmt in STACK_FORMATS or backend == "python", trace, game_jar)
    load_commands = emu.start()
    loaded = emu.profile  # the host ops listed are those after the load's setup
    with interruptible() as stopped:
        apply_setup(emu, click.get_current_context().meta.get("dpemu.run.order", []), sets, calls)
        with progress(ticks, "ticks", 200) as bar:
            for _ in range(ticks):
                emu.tick()
                bar.update(1)
                if stop and stop.met(emu):
                    break
    report = build_report(emu.profile, emu.packs.sources, loaded, load_commands)
    text = {"table": lambda: formats.write_table(report, top), "json": lambda: formats.write_json(report),
            "collapsed": lambda: formats.write_collapsed(report), "trace": lambda: trace.text()}[fmt]()
    written = write_output(output or "-", text if output else text.rstrip("\n"))
    for diag in emu.diagnostics:
        click.echo(diag.format(), err=True)
    grew = _check_baseline(saved, report, threshold, baseline) if saved is not None else False
    problems = has_errors(emu.load_diagnostics) or has_errors(emu.diagnostics)
    sys.exit(exit_status(problems, no_fail, written, stopped[0]) or (1 if grew else 0))


def _loaded(packs, mc_version: str | None, stacks: bool, trace, game_jar: str | None) -> Emulator:
    """An emulator with ``packs`` loaded: the numba VM, or the reference backend recording stacks."""
    emu = Emulator(backend="python", stacks=True, trace=trace) if stacks else Emulator(backend="numba")
    return load_or_usage_error(emu, packs, mc_version, game_jar)


def _check_baseline(saved: dict, report: dict, threshold: float, path: str) -> bool:
    """Print the functions that grew past ``threshold`` over the saved profile; True if any did."""
    grown = formats.compare(saved, report, threshold)
    for line in grown:
        click.echo(f"regression: {line}", err=True)
    if not grown:
        click.echo(f"no function grew more than {threshold:g}% over {path}", err=True)
    return bool(grown)


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
def build_report(prof: Profile, sources: dict, loaded: Profile, load_commands: int = 0) -> dict:
    """The report the formats write (:mod:`emulator.profile.formats`) from the profile ``prof``;
    ``loaded`` is the profile when the load's setup had run (its ``load_commands`` of the commands
    outside ticks were the load functions', the rest were --set/--call's)."""
    series = prof.ticks
    ops = _vm_ops() if prof.host is not None else {}  # the VM's opcode names (numba backend only)
    ids = set(prof.functions_self) | set(prof.functions_total) | set(prof.calls)
    functions = [{"function": f, "self": prof.functions_self.get(f, 0), "total": prof.functions_total.get(f),
                  "calls": prof.calls.get(f)} for f in ids]
    functions.sort(key=lambda f: (-(f["total"] if f["total"] is not None else f["self"]), f["function"]))
    report = {
        "backend": prof.backend,
        "limit": prof.limit,
        "commands": sum(series) + prof.outside_ticks,
        "outside_ticks": {"load": load_commands, "setup": prof.outside_ticks - load_commands},
        "ticks": {"count": len(series), "mean": sum(series) / len(series) if series else 0.0,
                  "max": max(series, default=0), "series": series},
        "roots": _roots(prof.roots, prof.limit),
        "functions": functions,
        "lines": [{"path": path, "line": line, "commands": count, "source": _source(sources, path, line),
                   "instructions": _vm_instructions(prof.instructions.get((path, line), []), ops)}
                  for (path, line), count in sorted(prof.lines.items(), key=lambda kv: (-kv[1], kv[0]))],
        # the python backend runs everything in Python: no VM/host split
        "host": None if prof.host is None else _vm_host(prof.host, loaded.host, sources, ops),
    }
    if prof.stacks is not None:
        report["stacks"] = {";".join(stack): count for stack, count in sorted(prof.stacks.items())}
    return report


def _roots(roots: dict[str, RootRuns], limit: int) -> list[dict]:
    rows = [{"function": function, "runs": r.runs, "max_cost": r.max_cost, "mean_cost": r.cost / r.runs,
             "headroom": limit - r.max_cost, "cut": r.cuts} for function, r in roots.items()]
    return sorted(rows, key=lambda r: -r["max_cost"])


def _source(sources: dict, path: str, line: int) -> str:
    lines = sources.get(path) or []
    return lines[line - 1].strip() if 0 < line <= len(lines) else ""


def _vm_ops() -> dict[int, str]:
    """The VM's instruction names by opcode, as ``dpemu disasm`` prints them (the opcode table)."""
    from emulator.vm.opcodes import BY_CODE

    return {code: op.name for code, op in BY_CODE.items()}


def _vm_instructions(counts: list[tuple[int, int]], names: dict[int, str]) -> list[dict]:
    """The cost charged at each VM instruction of a line (an execute stage, the final command, a
    call), in code order."""
    return [{"op": names.get(op, str(op)), "count": count} for op, count in counts]


# what each host opcode hands to Python, as the profile names it
HOST_KINDS = {"HOST": "command", "HOSTSTAGE": "stage", "HOSTSTORE": "store", "GETFIELD": "command",
              "STOREFIELD": "store", "SETLEAF": "command", "GETLEAF": "command", "STORELEAF": "store",
              "COPYLEAF": "command", "OBJECTIVE": "command"}


def _vm_host(runs: dict, loaded: dict, sources: dict, names: dict[int, str]) -> list[dict]:
    """The host ops Python ran after ``loaded`` (final commands, execute stages, stores) with how
    often each ran. Read from the backend's record of the ops it served, not from the VM's charged
    counts: a store is never charged, so the counts would hide a host-run store."""
    after = Counter(runs)
    after.subtract(loaded)
    rows = [{"function": function, "path": path, "line": line, "op": HOST_KINDS[names[op]],
             "command": _source(sources, path, line), "count": count}
            for (function, path, line, op), count in after.items() if count > 0]
    return sorted(rows, key=lambda r: (-r["count"], r["path"], r["line"]))
