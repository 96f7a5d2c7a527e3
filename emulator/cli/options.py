"""Options shared by the commands that run packs (``dpemu run``, ``dpemu profile``): parsing of
--set/--call/--watch/--until/--player and applying --set/--call in command-line order."""
from __future__ import annotations

import math

from dataclasses import dataclass

import click

from emulator.api import Emulator
from emulator.cli.params import PackPath, game_jar_option
from emulator.world.semantics import INT_MAX, INT_MIN


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


class OrderedCommand(click.Command):
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


def parse_set(text: str) -> tuple[str, str, int]:
    parts = text.split()
    if len(parts) != 3:
        raise click.BadParameter(f"--set {text!r}: expected \"HOLDER OBJECTIVE VALUE\"")
    if parts[0].startswith("@") or parts[0] == "*":
        raise click.BadParameter(f"--set {text!r}: HOLDER is a name (a player, #fake or $fake), not a selector")
    return parts[0], parts[1], _int32(parts[2], "--set value")


def parse_watch(text: str) -> Watch:
    parts = text.split()
    if len(parts) != 2:
        raise click.BadParameter(f"--watch {text!r}: expected \"HOLDER OBJECTIVE\"")
    return Watch(*parts)


def parse_until(text: str) -> Until:
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


def parse_player(text: str) -> tuple[str, tuple[float, ...], tuple[float, float], bool, str]:
    """``NAME@X,Y,Z[,YAW,PITCH][,air][,in=DIMENSION]``: the name, position, rotation, whether it
    stands on the ground (``air``: it is in the air) and its level (the overworld by default)."""
    name, _, numbers = text.partition("@")
    parts = [p.strip() for p in numbers.split(",")]
    on_ground, dimension = True, "minecraft:overworld"
    while parts and (parts[-1] == "air" or parts[-1].startswith("in=")):
        word = parts.pop()
        if word == "air":
            on_ground = False
        else:
            dimension = word[3:] if ":" in word else "minecraft:" + word[3:]
    try:
        values = [float(v) for v in parts]
    except ValueError:
        values = []
    if not name or len(values) not in (3, 5) or not all(map(math.isfinite, values)):
        raise click.BadParameter(f"{text!r}: expected NAME@X,Y,Z or NAME@X,Y,Z,YAW,PITCH (finite numbers), "
                                 "then ,air for a player in the air and ,in=DIMENSION for its level",
                                 param_hint="--player")
    return name, tuple(values[:3]), tuple(values[3:]) or (0.0, 0.0), on_ground, dimension


def parse_call(text: str) -> tuple[str, object]:
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


def apply_setup(emu: Emulator, order: list[str], sets: list, calls: list[tuple[str, object]]) -> int:
    """Start the world (``#minecraft:load`` runs first, as when a world loads, before any player
    command), then apply --set and --call in command-line order. Returns the load's commands."""
    load_commands = emu.start()
    sets_iter, calls_iter = iter(sets), iter(calls)
    for name in order:
        if name == "set_":
            holder, objective, value = next(sets_iter)
            if objective not in emu.objectives():
                raise click.UsageError(f"--set {holder} {objective} {value}: no objective {objective!r} "
                                       "(the packs' load did not create it)")
            emu.set_score(holder, objective, value)
        else:
            function, arguments = next(calls_iter)
            emu.call(function, arguments=arguments)
    return load_commands


def load_or_usage_error(emu: Emulator, packs, mc_version: str | None, game_jar: str | None = None) -> Emulator:
    """``emu`` with ``packs`` loaded (over the game's vanilla data from ``game_jar``); an unknown
    --mc is a usage error. The load's errors and warnings are printed (a pack the version ignores
    says so), its infos are not."""
    try:
        emu.load(list(packs), mc_version, game_jar=game_jar)
    except ValueError as error:
        raise click.BadParameter(str(error), param_hint="--mc") from None
    for diag in emu.load_diagnostics:
        if diag.severity != "info":
            click.echo(diag.format(), err=True)
    return emu


_MAX_TICKS = 2**31 - 1  # the game counts ticks in a long; a run this long is a typo, not a plan


def run_options(command):
    """The arguments ``dpemu run`` and ``dpemu profile`` share: PACKS, --ticks, --call, --set, --until,
    --game-jar."""
    decorators = [
        click.argument("packs", nargs=-1, required=True, type=PackPath()),
        click.option("--ticks", default=1, show_default=True, type=click.IntRange(0, _MAX_TICKS), help="Ticks to run."),
        click.option("--call", multiple=True, metavar='FN|"FN {ARGS}"',
                     help="Call a function (as the server) before ticking; macro arguments in SNBT."),
        click.option("--set", "set_", multiple=True, metavar='"HOLDER OBJ VALUE"', help="Set a score before ticking."),
        click.option("--until", metavar='"HOLDER OBJ RANGE"',
                     help="Stop after the tick where the score is in RANGE."),
        game_jar_option,
    ]
    for decorate in reversed(decorators):
        command = decorate(command)
    return command
