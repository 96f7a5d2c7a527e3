"""Parse the generated corpus with dpemu's parser and with mecha in the same run; print lines/s.

Usage: ``python bench/bench_parse.py [--lines N] [--repeat R] [--no-mecha] [--pack DIR]`` (``--pack``
parses an existing pack's functions instead of the generated corpus). Lines counts every
physical line (comments and blanks included), as a pack's size is usually quoted. Times are CPU
seconds of this process (``time.process_time``) and each parser's best of R runs is reported,
which damps the noise of other processes on a shared machine.
"""
from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from corpus import write_corpus  # noqa: E402

from mcfunction_parser.parse import parse_function  # noqa: E402


def _load(root: Path) -> list[tuple[str, str]]:
    return [(str(p), p.read_text()) for p in sorted(root.rglob("*.mcfunction"))]


def _ours(sources) -> int:
    errors = 0
    for path, text in sources:
        _, diagnostics = parse_function(text, path, "bench:f", (1, 21, 0))
        errors += len(diagnostics)
    return errors


def _mecha(sources) -> int:
    from mecha import DiagnosticError, Mecha

    mc = Mecha(version="1.21")
    errors = 0
    for _, text in sources:
        try:
            mc.parse(text, multiline=True)
        except DiagnosticError:
            errors += 1
        except Exception:  # mecha's tokenizer crashes on some inputs (e.g. '\\' continuations)
            errors += 1
    return errors


def _best(fn, sources, repeat: int) -> tuple[float, int]:
    best = float("inf")
    result = 0
    for _ in range(repeat):
        start = time.process_time()
        result = fn(sources)
        best = min(best, time.process_time() - start)
    return best, result


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--lines", type=int, default=40000)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--no-mecha", action="store_true")
    parser.add_argument("--pack", type=Path, help="parse this pack's .mcfunction files instead")
    args = parser.parse_args()
    if args.pack:
        sources = _load(args.pack)
    else:
        with tempfile.TemporaryDirectory() as tmp:
            write_corpus(tmp, args.lines, args.seed)
            sources = _load(Path(tmp))
    lines = sum(text.count("\n") for _, text in sources)
    ours, errors = _best(_ours, sources, args.repeat)
    print(f"dpemu : {lines} lines in {ours:.3f} CPU s = {lines / ours:,.0f} lines/s ({errors} diagnostics)")
    if args.no_mecha:
        return
    theirs, failures = _best(_mecha, sources, max(1, args.repeat // 2))
    print(f"mecha : {lines} lines in {theirs:.3f} CPU s = {lines / theirs:,.0f} lines/s ({failures} files rejected;"
          " mecha's 1.21 tree is 1.21.11, which renamed the corpus' 1.21.0 game rules)")
    print(f"ratio : dpemu is {theirs / ours:.1f}x mecha's speed")


if __name__ == "__main__":
    main()
