"""Parse the generated corpus with dpemu's parser and with mecha in the same run; print lines/s.

Usage: ``python bench/bench_parse.py [--lines N] [--repeat R] [--no-mecha] [--pack DIR]`` (``--pack``
parses an existing pack's functions instead of the generated corpus). Lines counts every
physical line (comments and blanks included), as a pack's size is usually quoted. Both CPU seconds
of this process (``time.process_time``) and wall seconds are printed; the speed and the ratio are
computed from CPU time, which other processes on a shared machine disturb far less than wall time.

The two parsers run interleaved (:func:`side_by_side`), so that both see the same load on a shared
machine: mecha parses the files in R slices (once in all), and dpemu parses all of them before the
first slice, between slices and after the last, its figure the best of those R + 1 runs. Run one
after the other, a change of load between dpemu's second and mecha's twenty moved the ratio by a
third from run to run.
"""
from __future__ import annotations

import argparse
import functools
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from corpus import write_corpus  # noqa: E402

from mcfunction_parser.parse import forget_read_lines, parse_function  # noqa: E402


def load_sources(root: Path) -> list[tuple[str, str]]:
    return [(str(p), p.read_text()) for p in sorted(root.rglob("*.mcfunction"))]


def parse_ours(sources) -> int:
    errors = 0
    for path, text in sources:
        _, diagnostics = parse_function(text, path, "bench:f", (1, 21, 0))
        errors += len(diagnostics)
    return errors


@functools.cache
def mecha_parser():
    """One mecha instance, built once and untimed (as dpemu's imports and tables are)."""
    from mecha import Mecha

    return Mecha(version="1.21")


def parse_mecha(sources) -> int:
    from mecha import DiagnosticError

    mc = mecha_parser()
    errors = 0
    for _, text in sources:
        try:
            mc.parse(text, multiline=True)
        except DiagnosticError:
            errors += 1
        except Exception:  # mecha's tokenizer crashes on some inputs (e.g. '\\' continuations)
            errors += 1
    return errors


def fresh() -> None:
    """Before each timed run of :func:`parse_ours`, untimed: the parser's memory of lines read
    (which relocates a line seen before instead of reading it again) starts empty, as in a fresh
    process; forgetting the last run's lines frees their nodes, work a fresh process does not do."""
    forget_read_lines()


def best_of(fn, sources, repeat: int, before=None) -> tuple[float, float, int]:
    """(best CPU seconds, best wall seconds, fn's result) over ``repeat`` runs, ``before()``
    called untimed before each."""
    cpu = wall = float("inf")
    result = 0
    for _ in range(repeat):
        if before is not None:
            before()
        start_cpu, start_wall = time.process_time(), time.perf_counter()
        result = fn(sources)
        cpu = min(cpu, time.process_time() - start_cpu)
        wall = min(wall, time.perf_counter() - start_wall)
    return cpu, wall, result


def side_by_side(sources, mecha_sources, slices: int):
    """(dpemu's (best CPU s, best wall s, diagnostics), mecha's (CPU s, wall s, files rejected)):
    dpemu on ``sources`` ``slices + 1`` times, each run fresh (see :func:`fresh`), interleaved with
    mecha on ``slices`` consecutive slices of ``mecha_sources``, its times summed."""
    slices = max(1, min(slices, len(mecha_sources)))
    mecha_parser()
    bounds = [len(mecha_sources) * i // slices for i in range(slices + 1)]
    ours = best_of(parse_ours, sources, 1, fresh)
    theirs_cpu = theirs_wall = 0.0
    failures = 0
    for i in range(slices):
        cpu, wall, rejected = best_of(parse_mecha, mecha_sources[bounds[i]:bounds[i + 1]], 1)
        theirs_cpu, theirs_wall, failures = theirs_cpu + cpu, theirs_wall + wall, failures + rejected
        again = best_of(parse_ours, sources, 1, fresh)
        ours = (min(ours[0], again[0]), min(ours[1], again[1]), again[2])
    return ours, (theirs_cpu, theirs_wall, failures)


def _line(name: str, lines: int, cpu: float, wall: float) -> str:
    return (f"{name}: {lines} lines in {cpu:.3f} CPU s = {lines / cpu:,.0f} lines/s"
            f" (wall {wall:.3f} s = {lines / wall:,.0f} lines/s)")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--lines", type=int, default=40000)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--no-mecha", action="store_true")
    parser.add_argument("--pack", type=Path, help="parse this pack's .mcfunction files instead")
    args = parser.parse_args()
    if args.pack:
        sources = load_sources(args.pack)
    else:
        with tempfile.TemporaryDirectory() as tmp:
            write_corpus(tmp, args.lines, args.seed)
            sources = load_sources(Path(tmp))
    lines = sum(text.count("\n") for _, text in sources)
    if args.no_mecha:
        ours, ours_wall, errors = best_of(parse_ours, sources, args.repeat, fresh)
        print(_line("dpemu", lines, ours, ours_wall) + f", {errors} diagnostics")
        return
    (ours, ours_wall, errors), (theirs, theirs_wall, failures) = side_by_side(sources, sources, args.repeat)
    print(_line("dpemu", lines, ours, ours_wall) + f", {errors} diagnostics (best of {args.repeat + 1} runs "
          "interleaved with mecha's slices)")
    print(_line("mecha", lines, theirs, theirs_wall) + f", {failures} files rejected"
          " (mecha's 1.21 tree is 1.21.11, which renamed the corpus' 1.21.0 game rules)")
    print(f"ratio: dpemu is {theirs / ours:.1f}x mecha's speed in CPU time ({theirs_wall / ours_wall:.1f}x in wall time)")

if __name__ == "__main__":
    main()
