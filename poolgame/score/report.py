"""The score's table, JSON and pictures from the cases' results."""
from __future__ import annotations

from collections import defaultdict
from pathlib import Path

import click

from poolgame.score.metrics import Row, percentiles, rows


def rows_of(results, models, modes) -> list[Row]:
    samples = defaultdict(list)
    for result in results:
        for key, values in result.samples.items():
            samples[key].extend(float(v) for v in values)
    return rows(samples, models, modes)


def _number(value) -> str:
    return "-" if value is None else f"{value:.3g}"


def text(table: list[Row], results, interrupted: bool, to_stderr: bool = False) -> str:
    lines = [f"{'model':<10} {'mode':<10} {'metric':<58} {'unit':<8} {'cases':>6} {'min':>9} {'p50':>9} {'p95':>9} "
             f"{'max':>9}  {'threshold':<12} result"]
    for row in table:
        m, stats = row.metric, percentiles(row.values)
        verdict = "-" if not row.values else ("info" if not m.scored else ("pass" if row.passed else "FAIL"))
        lines.append(f"{m.model:<10} {m.mode:<10} {m.text:<58} {m.unit:<8} {len(row.values):>6} "
                     f"{_number(stats['min']):>9} {_number(stats['p50']):>9} {_number(stats['p95']):>9} {_number(stats['max']):>9}  "
                     f"{m.threshold:<12} {verdict}")
    for result in results:
        if result.refused:
            lines.append(f"{result.name}: shot refused: {'; '.join(result.refused)}")
        if result.unfinished:
            lines.append(f"{result.name}: the table was still moving after the last tick")
    failed = [row.metric.key for row in table if not row.passed]
    done = f"{len(results)} cases" + (" (interrupted: Ctrl-C)" if interrupted else "")
    lines.append(f"{done}; {len(table) - len(failed)} of {len(table)} rows pass"
                 + (f"; failing: {', '.join(failed)}" if failed else ""))
    return "\n".join(lines)


def to_json(table: list[Row], results, seed: int, shots: int) -> dict:
    return {"seed": seed, "shots": shots, "rows": [row.to_json() for row in table],
            "cases": [{"name": r.name, "model": r.model, "refused": r.refused, "unfinished": r.unfinished,
                       "samples": {k: [float(v) for v in vs] for k, vs in r.samples.items()}} for r in results]}


def plot(folder: Path, table: list[Row], results) -> bool:
    """paths.png, histograms.png, growth.png in ``folder``; False (with the reason) when a write fails."""
    from poolgame import plots
    try:
        plots.score_paths(folder / "paths.png", results)
        plots.histograms(folder / "histograms.png", table)
        plots.growth(folder / "growth.png", results)
    except OSError as error:
        click.echo(f"error: could not write the plots in {folder}: {error.strerror or error}", err=True)
        return False
    return True
