"""Pool datapack benchmark on the emulator (numba backend), commands as the emulator counts them
(each command per context, each execute stage with a modifier, each function call):

- idle: a racked table at rest, one player online (the controls run for every player);
- rolling: the cue ball rolling across a racked table (15 balls at rest), mean and max per tick;
- break: the full-power break, mean and max per tick, and the max over ticks without events;
- overflow sweep: random shots (angle, speed up to full power, tip offset within the miscue
  limit, elevation) from the rack, every tenth a full-power break, with the overflow sanitizer;
  counts wrapped values, runtime diagnostics, tables that did not come to rest and balls left
  overlapping or off the table, and reports the commands per tick (max over the sweep, shots over
  the budget), the ticks in slow motion (a physics tick carried over) and the wall time per shot.

Each sweep worker loads the pack once and starts every shot on a fresh world
(poolgame.shot.reset_table); the shots are split over --jobs processes.

Usage: python bench/bench_pool.py [--shots N] [--seed S] [--jobs J]   (the issue's sweep: --shots 1000)
"""
from __future__ import annotations

import argparse
import itertools
import math
import multiprocessing
import os
import random
import time
from dataclasses import dataclass

from poolgame.physics.constants import BALL_RADIUS, TABLE_LENGTH, TABLE_WIDTH
from poolgame.shot import BREAK, BallOutcome, Shot, new_table, play, random_shot, reset_table, strike

BUDGET_MOVING, BUDGET_IDLE = 5000, 50
R_MM, L_MM, W_MM = BALL_RADIUS * 1e3, TABLE_LENGTH * 1e3, TABLE_WIDTH * 1e3


def idle_cost() -> int:
    return new_table().tick()           # new_table's player is online: the controls run for it


def shot_costs(shot: Shot) -> tuple[list[int], list[int]]:
    """Commands per tick until rest, and the same for the ticks without events."""
    emu = new_table()
    strike(emu, shot)
    costs, quiet = [], []
    while emu.score("$resting", "pool.game") == 0 and len(costs) < 2000:
        costs.append(emu.tick())
        if emu.score("#events.count", "pool.tmp") == 0:
            quiet.append(costs[-1])
    return costs, quiet


@dataclass(frozen=True)
class SweepShot:
    """One shot of the overflow sweep: what the sanitizer and the counters saw."""
    k: int
    ticks: int
    max_commands: int
    overflows: int
    diagnostics: int
    at_rest: bool
    refused: bool
    misplaced: int               # balls in play off the playing area or overlapping another at rest
    carried: int                 # ticks in slow motion (a physics tick carried over)
    seconds: float               # wall time: fresh world, strike, ticks until rest


def misplaced_balls(balls: list[BallOutcome]) -> int:
    """Balls in play whose centre is off the area R..L-R x R..W-R, or closer than 2R - 2 um to
    another ball's (1 um rounding either way)."""
    in_play = [b for b in balls if not b.pocketed]
    off = {b.id for b in in_play if not (R_MM <= b.x_mm <= L_MM - R_MM and R_MM <= b.z_mm <= W_MM - R_MM)}
    touching = [pair for pair in itertools.combinations(in_play, 2)
                if math.dist((pair[0].x_mm, pair[0].z_mm), (pair[1].x_mm, pair[1].z_mm)) < 2 * R_MM - 0.002]
    close = {b.id for pair in touching for b in pair}
    return len(off | close)


_worker_emu = None


def _sweep_worker_start() -> None:
    global _worker_emu
    _worker_emu = new_table(sanitize=True)


def _sweep_one(job: tuple[int, Shot]) -> SweepShot:
    k, shot = job
    started = time.perf_counter()
    emu = reset_table(_worker_emu)
    result = play(emu, shot)
    return SweepShot(k, result.ticks, result.commands_max, len(result.overflows), len(result.diagnostics),
                     result.at_rest, bool(result.refused), misplaced_balls(result.balls), result.carried,
                     time.perf_counter() - started)


def overflow_sweep(shots: int, seed: int, jobs: int) -> list[SweepShot]:
    rng = random.Random(seed)
    work = [(k, random_shot(rng, k)) for k in range(shots)]
    if jobs <= 1:
        _sweep_worker_start()
        return [_sweep_one(job) for job in work]
    with multiprocessing.get_context("fork").Pool(jobs, initializer=_sweep_worker_start) as pool:
        return list(pool.imap(_sweep_one, work, chunksize=4))


def _row(name: str, costs: list[int], budget: int) -> str:
    mean = sum(costs) / len(costs)
    return f"{name:<28} {mean:>9.0f} {max(costs):>9d} {budget:>9d}  {'ok' if max(costs) <= budget else 'OVER'}"


def _sweep_report(results: list[SweepShot], seed: int, jobs: int, seconds: float) -> list[str]:
    if not results:
        return [f"overflow sweep: 0 shots (seed {seed})"]
    worst = max(results, key=lambda r: r.max_commands)
    over = [r.k for r in results if r.max_commands > BUDGET_MOVING]
    walls = sorted(r.seconds for r in results)
    lines = [
        f"overflow sweep: {len(results)} shots (seed {seed}), {sum(r.ticks for r in results)} ticks, "
        f"{sum(r.overflows for r in results)} wrapped values, {sum(r.diagnostics for r in results)} runtime "
        f"diagnostics, {sum(not r.at_rest for r in results)} not at rest, {sum(r.refused for r in results)} refused, "
        f"{sum(r.misplaced for r in results)} balls overlapping or off the table at rest; "
        f"{sum(r.carried for r in results)} ticks in slow motion",
        _row("sweep, max per shot", [r.max_commands for r in results], BUDGET_MOVING)
        + f"  (worst: shot {worst.k}; {len(over)} shots over the budget{': ' + str(over[:20]) if over else ''})",
        f"wall time per shot: mean {sum(walls) / len(walls):.2f} s, median {walls[len(walls) // 2]:.2f} s, "
        f"max {walls[-1]:.2f} s; sweep {seconds:.0f} s on {jobs} process(es)",
    ]
    return lines


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--shots", type=int, default=100)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--jobs", type=int, default=min(2, os.cpu_count() or 1),
                        help="sweep processes (default: 2, or 1 on a single core)")
    args = parser.parse_args()
    print(f"{'commands per tick':<28} {'mean':>9} {'max':>9} {'budget':>9}")
    print(_row("idle", [idle_cost()], BUDGET_IDLE))
    rolling, _ = shot_costs(Shot(angle=90.0, speed=1.5))
    print(_row("rolling (1 of 16 moving)", rolling, BUDGET_MOVING))
    brk, quiet = shot_costs(BREAK)
    print(_row("break (16 balls)", brk, BUDGET_MOVING))
    print(_row("break, ticks without events", quiet, BUDGET_MOVING))
    started = time.perf_counter()
    results = overflow_sweep(args.shots, args.seed, args.jobs)
    for line in _sweep_report(results, args.seed, args.jobs, time.perf_counter() - started):
        print(line, flush=True)


if __name__ == "__main__":
    main()
