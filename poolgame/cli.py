"""``dpemu shot``: play one pool shot on the pool datapack and print where every ball went."""
from __future__ import annotations

import json
import sys
from pathlib import Path

import click

from emulator.cli.outcome import CLEAN, PROBLEMS, exit_status, fail_option, has_errors, progress
from emulator.cli.params import FiniteFloat, OutputPath, PackPath, write_output


BALL_NAMES = {0: "cue"}


def _game():
    """The shot driver (poolgame.shot), imported when a shot is played: ``dpemu --help`` lists this
    command without loading the emulator."""
    from poolgame import shot as game

    return game


def _tip(text: str) -> tuple[float, float]:
    parts = text.split(",")
    if len(parts) != 2:
        raise click.BadParameter(f"{text!r}: expected X,Y (fractions of the ball radius, e.g. 0.2,-0.3)",
                                 param_hint="--tip")
    number = FiniteFloat()
    try:
        x, y = (number.convert(v, None, None) for v in parts)
    except click.BadParameter as error:
        raise click.BadParameter(f"{text!r}: {error.message}", param_hint="--tip") from None
    return x, y


def _shot(break_: bool, angle, speed, tip, elevation):
    aimed = [o for o, v in (("--angle", angle), ("--speed", speed), ("--tip", tip), ("--elevation", elevation))
             if v is not None]
    if break_:
        if aimed:
            raise click.UsageError(f"--break plays the break shot; it takes no {', '.join(aimed)}")
        return _game().BREAK
    if speed is None:
        raise click.UsageError("give --break, or a shot with at least --speed M/S")
    tip_x, tip_y = _tip(tip) if tip is not None else (0.0, 0.0)
    shot = _game().Shot(angle or 0.0, speed, tip_x, tip_y, elevation or 0.0)
    too_big = [k for k, v in shot.macro_arguments().items() if abs(v) >= 2 ** 31]
    if too_big:
        raise click.UsageError(f"{', '.join(too_big)}: far outside any shot the pack accepts")
    return shot


@click.command("shot")
@click.argument("pack", required=False, type=PackPath())
@click.option("--break", "break_", is_flag=True, help="The break: full power from the head spot at the rack's apex.")
@click.option("--angle", type=FiniteFloat(), metavar="DEG", help="Aim, degrees counter-clockwise from the table's long axis (+x) towards +z.")
@click.option("--speed", type=FiniteFloat(), metavar="M/S", help="Cue speed (the pack accepts 0.001..6.5).")
@click.option("--tip", metavar="X,Y", help="Tip offset right and up, fractions of the ball radius (X^2 + Y^2 <= 0.25).")
@click.option("--elevation", type=FiniteFloat(), metavar="DEG", help="Cue elevation, degrees (0..89).")
@click.option("--max-ticks", default=2000, show_default=True, type=click.IntRange(min=1))
@click.option("--backend", type=click.Choice(["numba", "python"]), default="numba", show_default=True)
@click.option("--sanitize", is_flag=True, help="Report every arithmetic result that wraps int32.")
@click.option("--json", "json_out", type=OutputPath(), metavar="FILE|-", help="Write the outcome as JSON.")
@click.option("--trajectory", is_flag=True, help="The JSON gains every ball's position after each physics tick and the events.")
@click.option("--plot", "plot_out", type=OutputPath(stdout=False), metavar="FILE.png",
              help="Draw the table, the balls' paths and the events (needs matplotlib: dpemu[plot]).")
@fail_option
def shot(pack, break_, angle, speed, tip, elevation, max_ticks, backend, sanitize, json_out, trajectory, plot_out,
         no_fail) -> None:
    """Set up a table with the pool datapack PACK (a folder or .zip file; default: the pool
    datapack that ships with dpemu), rack, strike, and emulate until the table is at rest. Exit
    status 1 when the pack refuses the shot, the table does not come to rest within --max-ticks,
    the run had errors or the sanitizer finds a wrapped value."""
    game = _game()
    chosen = _shot(break_, angle, speed, tip, elevation)
    if trajectory and not json_out:
        raise click.UsageError("--trajectory adds to the JSON: give --json FILE|- too")
    if plot_out:
        from poolgame.plots import MissingMatplotlib, pyplot
        try:
            pyplot()
        except MissingMatplotlib as error:
            raise click.UsageError(str(error)) from None
    pack = pack or game.DEFAULT_PACK
    if not pack.exists():
        raise click.UsageError(f"no pool datapack at {pack}: give the pack's folder or .zip file as PACK")
    emu = game.new_table(pack, backend, sanitize)
    for diag in emu.load_diagnostics:
        if diag.severity == "error":
            click.echo(diag.format(), err=True)
    missing = game.missing_functions(emu)
    if missing:
        click.echo(f"{pack}: not a pool datapack (no {', '.join(missing)})", err=True)
        sys.exit(1)
    with progress(max_ticks, "ticks", 200) as bar:
        result = game.play(emu, chosen, max_ticks, on_tick=lambda: bar.update(1), record=bool(trajectory or plot_out))
    _print(result, to_stderr=json_out == "-")
    written = not json_out or write_output(json_out, json.dumps(result.to_json(trajectory), indent=2) + "\n")
    if plot_out and result.trajectory is not None:
        written = _plot(plot_out, chosen, result) and written
    problems = has_errors(emu.load_diagnostics) or has_errors(result.diagnostics) or bool(result.overflows)
    unfinished = bool(result.refused) or not result.at_rest
    status = exit_status(problems, no_fail, written, result.interrupted)
    sys.exit(status or (PROBLEMS if unfinished else CLEAN))


def _plot(path: str, chosen, result) -> bool:
    from poolgame.plots import shot_picture
    t = result.trajectory
    title = (f"angle {chosen.angle:g} deg, cue {chosen.speed:g} m/s, tip {chosen.tip_x:g},{chosen.tip_y:g}, "
             f"elevation {chosen.elevation:g} deg: {result.ticks} ticks")
    try:
        shot_picture(path, t.ids, t.positions_mm(), [e.to_json(t.ids) for e in t.events], title)
    except OSError as error:
        click.echo(f"error: could not write {path}: {error.strerror or error}", err=True)
        return False
    return True


def _print(result, to_stderr: bool) -> None:
    def out(line: str = "") -> None:
        click.echo(line, err=to_stderr)

    for message in result.refused:
        out(_game().in_player_units(message))
    if result.refused:
        return
    out(f"{'ball':>4}  {'x mm':>8}  {'z mm':>8}  outcome")
    for ball in result.balls:
        if ball.pocketed:
            outcome = f"pocketed at tick {ball.tick}"
        elif ball.moving:
            outcome = "still moving"
        else:
            outcome = f"stopped at tick {ball.tick}" if ball.tick is not None else "did not move"
        out(f"{BALL_NAMES.get(ball.id, ball.id):>4}  {ball.x_mm:8.1f}  {ball.z_mm:8.1f}  {outcome}")
    if result.interrupted:
        rest = "interrupted (Ctrl-C): table still moving"
    else:
        rest = "table at rest" if result.at_rest else "table still moving (--max-ticks reached)"
    out(f"{rest} after {result.ticks} ticks ({result.carried} in slow motion: a burst of events carried "
        f"over); commands per tick mean {result.commands_mean:.0f}, max {result.commands_max}; {result.seconds:.2f} s")
    for overflow in result.overflows:
        out(f"{overflow.loc}: overflow: {overflow.a} {overflow.op} {overflow.b} = {overflow.exact}, "
            f"stored {overflow.stored} (tick {overflow.tick})")
    for diag in result.diagnostics:
        out(diag.format())
