"""``dpemu run``: load packs, run ``#minecraft:load``, apply --set/--call in command-line order, tick,
report."""
from __future__ import annotations

import csv
import io
import json
import sys
import time

import click

from emulator.api import Emulator
from emulator.cli.options import (
    OrderedCommand, Until, Watch, apply_setup, load_or_usage_error, parse_call, parse_player, parse_set, parse_until,
    parse_watch, run_options,
)
from emulator.cli.outcome import exit_status, fail_option, has_errors, interruptible, progress
from emulator.cli.params import OutputPath, write_output
from emulator.runtime.auto import SWITCH_AFTER

PROGRESS_MIN_TICKS = 200  # show a progress bar from this many ticks on
BATCH_TICKS = 1000  # ticks run in one call when nothing is watched (Ctrl-C and the bar act between calls)


@click.command("run", cls=OrderedCommand)
@run_options
@click.option("--watch", multiple=True, metavar='"HOLDER OBJ"', help="Report this score (and per tick in --csv).")
@click.option("--backend", type=click.Choice(["auto", "numba", "python"]), default="auto", show_default=True,
              help=f"auto: the python backend, then the numba VM once the run has done {SWITCH_AFTER:,} commands' "
                   "work (a root counting as a few).")
@click.option("--sanitize", is_flag=True, help="Report every arithmetic result that wraps int32.")
@click.option("--json", "json_out", type=OutputPath(), metavar="FILE|-", help="Write the results as JSON.")
@click.option("--csv", "csv_out", type=OutputPath(), metavar="FILE|-", help="Watched values per tick.")
@click.option("--mc", "mc_version", metavar="VERSION", help="Game version to emulate (default: the packs').")
@click.option("--player", "players", multiple=True, metavar="NAME@X,Y,Z[,YAW,PITCH][,air][,in=DIM]",
              help="Add a simulated player before anything runs, on the ground (,air: in the air), in the "
                   "overworld (,in=DIM: in that dimension).")
@click.option("--shuffle", type=int, metavar="SEED", help="Visit unsorted @e in a seeded random order.")
@click.option("--log", "show_log", is_flag=True,
              help="Print the run's output lines by tick (say, tellraw and the other messages of --json's log).")
@fail_option
def run(packs, ticks, call, set_, until, game_jar, watch, backend, sanitize, json_out, csv_out, mc_version, players,
        shuffle, show_log, no_fail) -> None:
    """Emulate PACKS tick by tick.

    Runs #minecraft:load, applies --set and --call in order, then runs --ticks ticks."""
    sets = [parse_set(s) for s in set_]
    calls = [parse_call(c) for c in call]
    watches = [parse_watch(w) for w in watch]
    stop = parse_until(until) if until else None
    if stop and stop.watch not in watches:
        watches.append(stop.watch)
    players = [parse_player(p) for p in players]
    emu = load_or_usage_error(Emulator(backend=backend, sanitize=sanitize, shuffle=shuffle), packs, mc_version, game_jar)
    for name, pos, rotation, on_ground, dimension in players:
        try:
            emu.add_player(name, pos, rotation, on_ground=on_ground, dimension=dimension)
        except ValueError as error:  # a dimension the packs do not declare
            raise click.BadParameter(str(error), param_hint="--player") from None

    started = time.perf_counter()
    rows: list[list] = []
    load_commands = 0
    with interruptible() as stopped:
        load_commands = apply_setup(emu, click.get_current_context().meta.get("dpemu.run.order", []), sets, calls)
        _tick(emu, ticks, watches, stop, rows)
    wall = time.perf_counter() - started

    report = _report(emu, watches, stop, wall, load_commands)
    if show_log:
        _print_log(emu, to_stderr="-" in (json_out, csv_out))
    _print_summary(report, emu, to_stderr="-" in (json_out, csv_out))
    outputs = ((json_out, lambda: json.dumps(report, indent=1) + "\n"), (csv_out, lambda: _csv(watches, rows)))
    written = all([write_output(path, text()) for path, text in outputs if path])
    problems = has_errors(emu.load_diagnostics) or has_errors(emu.diagnostics) or bool(emu.overflows)
    sys.exit(exit_status(problems, no_fail, written, stopped[0]))


def _tick(emu: Emulator, ticks: int, watches: list[Watch], stop: Until | None, rows: list[list]) -> None:
    """Run the ticks, a row of watched values after each (kept in ``rows`` even if interrupted)."""
    with progress(ticks, "ticks", PROGRESS_MIN_TICKS) as bar:
        if not watches:  # nothing to read between the ticks: they run in batches (Emulator.tick(n))
            for start in range(0, ticks, BATCH_TICKS):
                n, first = min(BATCH_TICKS, ticks - start), emu.ticks + 1
                emu.tick(n)
                rows.extend([t] for t in range(first, emu.ticks + 1))
                bar.update(n)
            return
        for _ in range(ticks):
            emu.tick()
            rows.append([emu.ticks, *(_value(emu, w) for w in watches)])
            bar.update(1)
            if stop and stop.met(emu):
                break


def _csv(watches: list[Watch], rows: list[list]) -> str:
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(["tick", *(w.label for w in watches)])
    writer.writerows(rows)
    return out.getvalue()


def _value(emu: Emulator, w: Watch):
    value = emu.score(w.holder, w.objective)
    return "" if value is None else value


def _report(emu: Emulator, watches: list[Watch], stop: Until | None, wall: float, load_commands: int) -> dict:
    per_tick = emu.commands_per_tick
    outside = emu.commands_outside_ticks
    return {
        "ticks": emu.ticks,
        "commands": sum(per_tick) + outside,
        "load_commands": load_commands,
        "setup_commands": outside - load_commands,
        "commands_per_tick": per_tick,
        "commands_per_tick_mean": (sum(per_tick) / len(per_tick)) if per_tick else 0.0,
        "commands_per_tick_max": max(per_tick, default=0),
        "max_root_cost": emu.max_root_cost,
        "quota_headroom": emu.quota - emu.max_root_cost,
        "wall_time_s": round(wall, 6),
        "backend": emu.backend_ran,
        "watch": {w.label: emu.score(w.holder, w.objective) for w in watches},
        "until_met": stop.met(emu) if stop else None,
        "scores": emu.scores(),
        "entities": emu.entities(),
        "log": [entry.to_json() for entry in emu.log],
        "overflows": [o.to_json() for o in emu.overflows],
        "diagnostics": [d.to_json() for d in emu.diagnostics],
        "load_diagnostics": [d.to_json() | {"severity": d.severity} for d in emu.load_diagnostics],
    }


def _print_log(emu: Emulator, to_stderr: bool) -> None:
    """``--log``: each output line with its tick, its kind and where the command stands (a tellraw's
    component as the player reads it)."""
    for entry in emu.log:
        click.echo(entry.line(emu.state.version), err=to_stderr)


def _print_summary(report: dict, emu: Emulator, to_stderr: bool) -> None:
    """The human summary (on stderr when stdout carries the JSON)."""

    def out(text: str) -> None:
        click.echo(text, err=to_stderr)

    out(f"ticks: {report['ticks']}   commands: {report['commands']} (load {report['load_commands']}, "
        f"--set/--call {report['setup_commands']}, ticks {sum(report['commands_per_tick'])})   "
        f"wall: {report['wall_time_s']:.3f} s")
    out(f"commands/tick: mean {report['commands_per_tick_mean']:.1f}, max {report['commands_per_tick_max']}   "
        f"quota headroom: {report['quota_headroom']} (costliest root {report['max_root_cost']})")
    out(f"backend: {report['backend']}")
    for label, value in report["watch"].items():
        out(f"  {label} = {'unset' if value is None else value}")
    if report["until_met"] is not None:
        out(f"--until {'met' if report['until_met'] else 'not met'}")
    if report["overflows"]:
        out(f"overflows: {len(report['overflows'])} (first: {report['overflows'][0]['where']})")
    shown = emu.diagnostics[:20]
    for diag in shown:
        click.echo(diag.format(), err=True)
    if len(emu.diagnostics) > len(shown):
        click.echo(f"... and {len(emu.diagnostics) - len(shown)} more diagnostics", err=True)
