"""``dpemu run``: load packs, apply --set/--call in command-line order, tick, report."""
from __future__ import annotations

import csv
import json
import sys
import time
from contextlib import nullcontext
from dataclasses import dataclass

import click

from emulator.api import Emulator
from emulator.semantics import INT_MAX, INT_MIN

PROGRESS_MIN_TICKS = 200  # show a progress bar from this many ticks on


@dataclass(frozen=True)
class Watch:
    holder: str
    objective: str

    @property
    def label(self) -> str:
        return f"{self.holder} {self.objective}"


@dataclass(frozen=True)
class Until:
    watch: Watch
    lo: int | None
    hi: int | None

    def met(self, emu: Emulator) -> bool:
        value = emu.score(self.watch.holder, self.watch.objective)
        return value is not None and (self.lo is None or value >= self.lo) and (self.hi is None or value <= self.hi)


class _OrderedCommand(click.Command):
    """Remembers the order in which --set and --call were given (click groups them per option)."""

    def parse_args(self, ctx: click.Context, args: list[str]) -> list[str]:
        _, _, order = self.make_parser(ctx).parse_args(args=list(args))
        ctx.meta["dpemu.run.order"] = [p.name for p in order if p.name in ("set_", "call")]
        return super().parse_args(ctx, args)


def _int32(text: str, what: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise click.BadParameter(f"{what}: expected an integer, got {text!r}") from None
    if not INT_MIN <= value <= INT_MAX:
        raise click.BadParameter(f"{what}: {value} is outside the 32-bit range")
    return value


def _parse_set(text: str) -> tuple[str, str, int]:
    parts = text.split()
    if len(parts) != 3:
        raise click.BadParameter(f"--set {text!r}: expected \"HOLDER OBJECTIVE VALUE\"")
    return parts[0], parts[1], _int32(parts[2], "--set value")


def _parse_watch(text: str) -> Watch:
    parts = text.split()
    if len(parts) != 2:
        raise click.BadParameter(f"--watch {text!r}: expected \"HOLDER OBJECTIVE\"")
    return Watch(*parts)


def _parse_until(text: str) -> Until:
    parts = text.split()
    if len(parts) != 3:
        raise click.BadParameter(f"--until {text!r}: expected \"HOLDER OBJECTIVE RANGE\" (5, 1.., ..0, 1..9)")
    rng = parts[2]
    if ".." in rng:
        lo_text, hi_text = rng.split("..", 1)
        lo = _int32(lo_text, "--until range") if lo_text else None
        hi = _int32(hi_text, "--until range") if hi_text else None
        if lo is None and hi is None:
            raise click.BadParameter("--until range: '..' needs a bound")
    else:
        lo = hi = _int32(rng, "--until range")
    return Until(Watch(parts[0], parts[1]), lo, hi)


@click.command("run", cls=_OrderedCommand)
@click.argument("packs", nargs=-1, required=True, type=click.Path(exists=True, file_okay=False))
@click.option("--ticks", default=1, show_default=True, type=click.IntRange(min=0), help="Ticks to run.")
@click.option("--call", multiple=True, metavar='FN|"FN {ARGS}"',
              help="Call a function (as the server) before ticking; macro arguments in SNBT.")
@click.option("--set", "set_", multiple=True, metavar='"HOLDER OBJ VALUE"', help="Set a score before ticking.")
@click.option("--watch", multiple=True, metavar='"HOLDER OBJ"', help="Report this score (and per tick in --csv).")
@click.option("--until", metavar='"HOLDER OBJ RANGE"', help="Stop after the tick where the score is in RANGE.")
@click.option("--backend", type=click.Choice(["numba", "python"]), default="numba", show_default=True)
@click.option("--sanitize", is_flag=True, help="Report every arithmetic result that wraps int32.")
@click.option("--json", "json_out", metavar="FILE|-", help="Write the results as JSON.")
@click.option("--csv", "csv_out", metavar="FILE", type=click.Path(dir_okay=False), help="Watched values per tick.")
@click.option("--mc", "mc_version", metavar="VERSION", help="Game version to emulate (default: the packs').")
@click.option("--player", "players", multiple=True, metavar="NAME@X,Y,Z[,YAW,PITCH]",
              help="Add a simulated player before anything runs.")
@click.option("--shuffle", type=int, metavar="SEED", help="Visit unsorted @e in a seeded random order.")
def run(packs, ticks, call, set_, watch, until, backend, sanitize, json_out, csv_out, mc_version, players,
        shuffle) -> None:
    """Emulate PACKS: apply --set and --call in order, then run --ticks ticks."""
    sets = [_parse_set(s) for s in set_]
    calls = [_parse_call(c) for c in call]
    watches = [_parse_watch(w) for w in watch]
    stop = _parse_until(until) if until else None
    if stop and stop.watch not in watches:
        watches.append(stop.watch)
    players = [_parse_player(p) for p in players]
    emu = Emulator(backend=backend, sanitize=sanitize, shuffle=shuffle)
    try:
        emu.load(list(packs), mc_version)
    except ValueError as error:  # an unknown --mc version
        raise click.BadParameter(str(error), param_hint="--mc") from None
    for name, pos, rotation in players:
        emu.add_player(name, pos, rotation)
    for diag in emu.load_diagnostics:
        if diag.severity == "error":
            click.echo(diag.format(), err=True)

    started = time.perf_counter()
    _apply_setup(emu, click.get_current_context().meta.get("dpemu.run.order", []), sets, calls)
    rows = _tick(emu, ticks, watches, stop)
    wall = time.perf_counter() - started

    report = _report(emu, watches, stop, wall)
    _print_summary(report, emu, to_stderr=json_out == "-")
    if json_out:
        _write_json(json_out, report)
    if csv_out:
        with open(csv_out, "w", newline="") as handle:
            writer = csv.writer(handle)
            writer.writerow(["tick", *(w.label for w in watches)])
            writer.writerows(rows)


def _parse_player(text: str) -> tuple[str, tuple[float, ...], tuple[float, float]]:
    """``NAME@X,Y,Z[,YAW,PITCH]``."""
    name, _, numbers = text.partition("@")
    try:
        values = [float(v) for v in numbers.split(",")]
    except ValueError:
        values = []
    if not name or len(values) not in (3, 5):
        raise click.BadParameter(f"{text!r}: expected NAME@X,Y,Z or NAME@X,Y,Z,YAW,PITCH", param_hint="--player")
    return name, tuple(values[:3]), tuple(values[3:]) or (0.0, 0.0)


def _parse_call(text: str) -> tuple[str, object]:
    """``FN`` or ``FN {key: value}`` (macro arguments in SNBT, as after ``function``)."""
    if " " not in text.strip():
        return text.strip(), None
    from mcfunction_parser.ast import FunctionCall
    from mcfunction_parser.diagnostics import Loc
    from mcfunction_parser.parse import parse_command

    cmd, diagnostics = parse_command(f"function {text.strip()}", Loc("--call", 1, 1))
    errors = [d for d in diagnostics if d.severity == "error"]
    if errors or not isinstance(cmd, FunctionCall) or cmd.is_tag or cmd.with_source is not None:
        reason = errors[0].message if errors else "expected FN or \"FN {key: value}\""
        raise click.BadParameter(f"--call {text!r}: {reason}")
    return cmd.function, cmd.arguments


def _apply_setup(emu: Emulator, order: list[str], sets: list, calls: list[tuple[str, object]]) -> None:
    sets_iter, calls_iter = iter(sets), iter(calls)
    for name in order:
        if name == "set_":
            holder, objective, value = next(sets_iter)
            emu.set_score(holder, objective, value)
        else:
            function, arguments = next(calls_iter)
            emu.call(function, arguments=arguments)


def _tick(emu: Emulator, ticks: int, watches: list[Watch], stop: Until | None) -> list[list]:
    rows: list[list] = []
    bar = click.progressbar(length=ticks, label="ticks", file=sys.stderr) if ticks >= PROGRESS_MIN_TICKS else None
    with bar if bar is not None else nullcontext():
        for _ in range(ticks):
            emu.tick()
            rows.append([emu.ticks, *(_value(emu, w) for w in watches)])
            if bar is not None:
                bar.update(1)
            if stop and stop.met(emu):
                break
    return rows


def _value(emu: Emulator, w: Watch):
    value = emu.score(w.holder, w.objective)
    return "" if value is None else value


def _report(emu: Emulator, watches: list[Watch], stop: Until | None, wall: float) -> dict:
    per_tick = emu.commands_per_tick
    limit = emu.state.gamerules.max_command_chain_length
    return {
        "ticks": emu.ticks,
        "commands": sum(per_tick) + emu.runtime.commands_outside_ticks,
        "commands_per_tick": per_tick,
        "commands_per_tick_mean": (sum(per_tick) / len(per_tick)) if per_tick else 0.0,
        "commands_per_tick_max": max(per_tick, default=0),
        "max_root_cost": emu.max_root_cost,
        "quota_headroom": limit - emu.max_root_cost,
        "wall_time_s": round(wall, 6),
        "watch": {w.label: emu.score(w.holder, w.objective) for w in watches},
        "until_met": stop.met(emu) if stop else None,
        "scores": emu.scores(),
        "entities": emu.entities(),
        "log": [entry.to_json() for entry in emu.log],
        "overflows": [o.to_json() for o in emu.overflows],
        "diagnostics": [d.to_json() for d in emu.diagnostics],
        "load_diagnostics": [d.to_json() | {"severity": d.severity} for d in emu.load_diagnostics],
    }


def _print_summary(report: dict, emu: Emulator, to_stderr: bool) -> None:
    """The human summary (on stderr when stdout carries the JSON)."""

    def out(text: str) -> None:
        click.echo(text, err=to_stderr)

    out(f"ticks: {report['ticks']}   commands: {report['commands']}   wall: {report['wall_time_s']:.3f} s")
    out(f"commands/tick: mean {report['commands_per_tick_mean']:.1f}, max {report['commands_per_tick_max']}   "
        f"quota headroom: {report['quota_headroom']} (costliest root {report['max_root_cost']})")
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


def _write_json(target: str, report: dict) -> None:
    text = json.dumps(report, indent=1)
    if target == "-":
        click.echo(text)
    else:
        with open(target, "w") as handle:
            handle.write(text + "\n")
