"""dpemu score at scale: many random shots as independent worlds of one compiled program, over local
processes (poolgame.score.sweep), and the full score sweep.

1. shots: N random full shots from the rack (poolgame.shot.random_shot: any aim, up to full power,
   any tip within the miscue limit, every tenth the break), each played to rest on a fresh world
   (numba VM, overflow sanitizer on, every complete tick recorded), split over --workers
   processes forked after the pack is compiled; the wall time beside the target, 1,000 shots in
   60 s on two cores.
2. score (with --score): every model with --cases random cases each, seeded and end to end: the
   rows, as `dpemu score` prints them, and the wall time.

Usage: python bench/bench_score.py [--shots 1000] [--workers 2] [--seed 1] [--score] [--cases 50]
"""
from __future__ import annotations

import argparse
import os
import random
import time

from poolgame.score import MODELS, report
from poolgame.score.cases import Case, cases, rounded
from poolgame.score.run import open_pack
from poolgame.score.sweep import sweep
from poolgame.shot import DEFAULT_PACK, random_shot

TARGET_SHOTS, TARGET_SECONDS = 1000, 60.0


def _cpu_seconds() -> float:
    """CPU time of this process and of its finished children (the sweep's workers)."""
    times = os.times()
    return times.user + times.system + times.children_user + times.children_system


def random_shots(n: int, workers: int, seed: int) -> tuple[float, float, int, float]:
    """(wall seconds, CPU seconds of every process, shots not at rest, wrapped values) of ``n``
    random full shots over ``workers`` processes (the pack compiled before: call open_pack first)."""
    rng = random.Random(seed)
    work = [Case(f"random {k}", "shots", shot=rounded(random_shot(rng, k))) for k in range(n)]
    started, cpu = time.perf_counter(), _cpu_seconds()
    results, _ = sweep(work, str(DEFAULT_PACK), modes=(), workers=workers)
    seconds, cpu = time.perf_counter() - started, _cpu_seconds() - cpu
    return seconds, cpu, sum(r.unfinished for r in results), sum(sum(r.samples.get("overflow", [])) for r in results)


def shots_bench(n: int, workers: int, seed: int) -> None:
    seconds, cpu, unfinished, wrapped = random_shots(n, workers, seed)
    rate = n / seconds
    print(f"random full shots: {n} in {seconds:.1f} s on {workers} process(es) = {rate:.1f} shots/s, "
          f"{1000 * cpu / n:.0f} ms of CPU a shot ({unfinished} not at rest, {wrapped:.0f} wrapped values)")
    # the CPU time says what the shots cost when other work shares the cores: on idle cores the
    # wall time tends to CPU time / workers
    print(f"{'':<36} {'measured':>10} {'target':>8}")
    for label, secs in ((f"1,000 shots, wall", TARGET_SHOTS * seconds / n),
                        (f"1,000 shots, CPU / {workers} worker(s)", TARGET_SHOTS * cpu / n / workers)):
        print(f"{label:<36} {secs:>8.1f} s {TARGET_SECONDS:>6.0f} s  "
              f"{'ok' if secs <= TARGET_SECONDS else 'SLOWER'} ({TARGET_SECONDS / secs:.2f}x the target rate)")


def score_bench(n: int, workers: int, seed: int) -> None:
    work = cases(MODELS, n, seed)
    started = time.perf_counter()
    results, _ = sweep(work, str(DEFAULT_PACK), ("seeded", "end-to-end"), workers)
    table = report.rows_of(results, MODELS, ("seeded", "end-to-end"))
    print(report.text(table, results, False))
    print(f"score sweep: {len(work)} cases in {time.perf_counter() - started:.0f} s on {workers} process(es)")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--shots", type=int, default=TARGET_SHOTS)
    parser.add_argument("--workers", type=int, default=min(2, os.cpu_count() or 1))
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--score", action="store_true", help="also run the full score sweep")
    parser.add_argument("--cases", type=int, default=50, help="random cases per model in the score sweep")
    args = parser.parse_args()
    problem = open_pack(str(DEFAULT_PACK))          # compiled once, before the workers fork
    if problem:
        raise SystemExit(problem)
    shots_bench(args.shots, args.workers, args.seed)
    if args.score:
        score_bench(args.cases, args.workers, args.seed)


if __name__ == "__main__":
    main()
