"""Pool datapack benchmark on the emulator (numba backend), commands as the emulator counts them
(each command per context, each execute stage with a modifier, each function call):

- idle: a racked table at rest, one player online (the controls run for every player);
- rolling: the cue ball rolling across a racked table (15 balls at rest), mean and max per tick;
- break: the full-power break, mean and max per tick, and the max over ticks without events;
- overflow sweep: random shots (angle, speed up to full power, tip offset within the miscue
  limit, elevation) from the rack, every tenth a full-power break, with the overflow sanitizer;
  counts wrapped values, runtime diagnostics and tables that did not come to rest.

Usage: python bench/bench_pool.py [--shots N] [--seed S]   (the issue's sweep: --shots 1000)
"""
from __future__ import annotations

import argparse
import random
import time

from emulator.shot import BREAK, Shot, new_table, play, random_shot, strike

BUDGET_MOVING, BUDGET_IDLE = 5000, 50


def idle_cost() -> int:
    emu = new_table()
    emu.add_player("Steve")
    return emu.tick()


def shot_costs(shot: Shot) -> tuple[list[int], list[int]]:
    """Commands per tick until rest, and the same for the ticks without events."""
    emu = new_table()
    strike(emu, shot)
    costs, quiet = [], []
    while emu.score("$resting", "pool.game") == 0 and len(costs) < 2000:
        costs.append(emu.tick())
        if emu.score("#events", "pool.tmp") == 0:
            quiet.append(costs[-1])
    return costs, quiet


def overflow_sweep(shots: int, seed: int) -> dict:
    rng = random.Random(seed)
    emu = new_table(sanitize=True)
    totals = {"shots": shots, "overflows": 0, "diagnostics": 0, "not_at_rest": 0, "refused": 0, "ticks": 0}
    for k in range(shots):
        emu.call("pool:table/setup", at=(0.0, 64.0, 0.0))
        result = play(emu, random_shot(rng, k))
        totals["overflows"] = len(result.overflows)          # the emulator's lists accumulate
        totals["diagnostics"] = len(result.diagnostics)
        totals["not_at_rest"] += not result.at_rest
        totals["refused"] += bool(result.refused)
        totals["ticks"] += result.ticks
    return totals


def _row(name: str, costs: list[int], budget: int) -> str:
    mean = sum(costs) / len(costs)
    return f"{name:<28} {mean:>9.0f} {max(costs):>9d} {budget:>9d}  {'ok' if max(costs) <= budget else 'OVER'}"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--shots", type=int, default=100)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    print(f"{'commands per tick':<28} {'mean':>9} {'max':>9} {'budget':>9}")
    print(_row("idle", [idle_cost()], BUDGET_IDLE))
    rolling, _ = shot_costs(Shot(angle=90.0, speed=1.5))
    print(_row("rolling (1 of 16 moving)", rolling, BUDGET_MOVING))
    brk, quiet = shot_costs(BREAK)
    print(_row("break (16 balls)", brk, BUDGET_MOVING))
    print(_row("break, ticks without events", quiet, BUDGET_MOVING))
    started = time.perf_counter()
    totals = overflow_sweep(args.shots, args.seed)
    seconds = time.perf_counter() - started
    print(f"overflow sweep: {totals['shots']} shots (seed {args.seed}), {totals['ticks']} ticks, "
          f"{totals['overflows']} wrapped values, {totals['diagnostics']} runtime diagnostics, "
          f"{totals['not_at_rest']} not at rest, {totals['refused']} refused; {seconds:.0f} s")


if __name__ == "__main__":
    main()
