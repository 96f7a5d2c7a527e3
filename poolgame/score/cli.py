"""``dpemu score``: the pool pack's integer physics scored against the float reference, one row per
metric, seeded and end to end (poolgame.score)."""
from __future__ import annotations

import json
import os
import sys
from pathlib import Path

import click

from emulator.cli.outcome import CLEAN, INTERRUPTED, PROBLEMS, USAGE, progress
from emulator.cli.params import OutputPath, PackPath, write_output
from poolgame.score import MODELS

MODES = {"seeded": ("seeded",), "end-to-end": ("end-to-end",), "both": ("seeded", "end-to-end")}


def _plot_dir(value: str | None) -> Path | None:
    """The plot folder, created when its parent exists; refused before any work when it cannot be
    written or matplotlib is missing."""
    if value is None:
        return None
    folder = Path(value)
    try:
        folder.mkdir(exist_ok=True)
    except OSError as error:
        raise click.BadParameter(f"{value}: {error.strerror or error}", param_hint="--plot") from None
    if not folder.is_dir() or not os.access(folder, os.W_OK):
        raise click.BadParameter(f"{value}: not a folder this user can write", param_hint="--plot")
    from poolgame.plots import MissingMatplotlib, pyplot
    try:
        pyplot()
    except MissingMatplotlib as error:
        raise click.UsageError(str(error)) from None
    return folder


@click.command("score")
@click.argument("pack", required=False, type=PackPath())
@click.option("--model", "models", multiple=True, type=click.Choice(MODELS),
              help="Score only this model (repeat for more; default: all).")
@click.option("--shots", default=10, show_default=True, type=click.IntRange(min=1),
              help="Random cases per model, beside the named ones.")
@click.option("--seed", default=1, show_default=True, type=int, help="Seed of the random cases.")
@click.option("--mode", type=click.Choice(list(MODES)), default="both", show_default=True)
@click.option("--json", "json_out", type=OutputPath(), metavar="FILE|-", help="Write the rows (and each case's) as JSON.")
@click.option("--plot", "plot_dir", metavar="DIR", help="Write PNG pictures here (needs matplotlib: dpemu[plot]).")
@click.option("--workers", default=min(2, os.cpu_count() or 1), show_default=True, type=click.IntRange(min=1),
              help="Local worker processes.")
@click.option("--scheduler", metavar="ADDRESS", help="Run the cases on this Dask scheduler (dpemu[distributed]).")
def score(pack, models, shots, seed, mode, json_out, plot_dir, workers, scheduler) -> None:
    """Score the pool datapack PACK (default: the one that ships with dpemu) against the float
    reference: each model alone swept over its inputs and whole shots, seeded (the float restarts
    from the integers after each event) and end to end. Exit status 1 when a row fails."""
    from poolgame.score import report
    from poolgame.score.cases import cases
    from poolgame.score.run import open_pack
    from poolgame.score.sweep import MissingExtra, sweep

    plots = _plot_dir(plot_dir)
    chosen = models or MODELS
    modes = MODES[mode]
    from poolgame.shot import DEFAULT_PACK
    pack = pack or DEFAULT_PACK
    problem = open_pack(str(pack))
    if problem:
        click.echo(f"{pack}: {problem}", err=True)
        sys.exit(USAGE)
    work = cases(chosen, shots, seed)
    with progress(len(work), "cases", 2) as bar:
        try:
            results, interrupted = sweep(work, str(pack), modes, workers, scheduler, paths=plots is not None,
                                         on_done=lambda _: bar.update(1))
        except MissingExtra as error:
            raise click.UsageError(str(error)) from None
    table = report.rows_of(results, chosen, modes)
    click.echo(report.text(table, results, interrupted, to_stderr=json_out == "-"), err=json_out == "-")
    written = not json_out or write_output(json_out, json.dumps(report.to_json(table, results, seed, shots), indent=2) + "\n")
    if plots is not None and results:
        written = report.plot(plots, table, results) and written
    if interrupted:
        sys.exit(INTERRUPTED)
    failed = any(not row.passed for row in table) or not written or any(r.refused or r.unfinished for r in results)
    sys.exit(PROBLEMS if failed else CLEAN)
