"""One case scored: played on the emulator (the numba VM, overflow sanitizer on), then judged
seeded and end to end. Each worker process loads the pack once and plays every case of its share on
a fresh world of that one compiled program (poolgame.shot.reset_table)."""
from __future__ import annotations

from collections import defaultdict
from dataclasses import dataclass, field
from pathlib import Path

from poolgame.score import direct, endtoend, seeded
from poolgame.score.cases import W, Case, mirror
from poolgame.score.constants import NotPoolPack, pack_constants
from poolgame.shot import missing_functions, new_table, play, reset_table
from poolgame.trajectory import VX, VZ, X, Z

MAX_TICKS = 2000


@dataclass
class CaseResult:
    name: str
    model: str
    samples: dict = field(default_factory=dict)   # metric key -> values
    refused: list = field(default_factory=list)
    unfinished: bool = False                      # the table still moved after MAX_TICKS
    paths: dict | None = None                     # for the plots: ids, integer, seeded and end-to-end positions (mm), events


_tables: dict = {}


def open_pack(pack: str) -> str | None:
    """Load and compile ``pack`` in this process (worker processes forked later share it); None, or
    why it is not the pool pack."""
    emu = new_table(Path(pack), sanitize=True)
    errors = [d.format() for d in emu.load_diagnostics if d.severity == "error"]
    missing = missing_functions(emu)
    if missing:
        return f"not the pool datapack (no {', '.join(missing)})" + "".join(f"\n{e}" for e in errors[:5])
    try:
        _tables[pack] = (emu, pack_constants(emu))
    except NotPoolPack as error:
        return f"not the pool datapack: {error}"
    return None


def _table(pack: str):
    """This process's emulator for ``pack`` (loaded and compiled once) and the pack's constants."""
    if pack not in _tables:
        problem = open_pack(pack)
        if problem:
            raise NotPoolPack(problem)
    return _tables[pack]


def score_case(case: Case, pack: str, modes=("seeded", "end-to-end"), paths: bool = False) -> CaseResult:
    emu, k = _table(pack)
    samples: dict = defaultdict(list)
    result = CaseResult(case.name, case.model)
    if case.kind == "collide":
        direct.collide(emu, case.inputs, samples)
    elif case.kind == "rebound":
        direct.rebound(emu, case.inputs, k, samples)
    elif case.kind == "strike":
        result.refused = direct.cue_strike(emu, case.shot, k, samples)
    else:
        _table_case(emu, k, case, modes, samples, result, paths)
    result.samples = dict(samples)
    return result


def _play(emu, balls, shot):
    first = len(emu.overflows)
    outcome = play(reset_table(emu, balls), shot, MAX_TICKS, record=True)
    return outcome, len(emu.overflows) - first


def _table_case(emu, k, case: Case, modes, samples, result: CaseResult, paths: bool) -> None:
    outcome, overflows = _play(emu, case.balls, case.shot)
    samples["overflow"].append(float(overflows))
    result.refused, result.unfinished = outcome.refused, not outcome.at_rest
    trajectory = outcome.trajectory
    if trajectory is None or not trajectory.ticks:
        return
    seeded_paths = e2e_paths = None
    if "seeded" in modes:
        seeded_paths = seeded.score(trajectory, k, samples)
        seeded.energy(trajectory, samples)
    if "end-to-end" in modes:
        e2e_paths = endtoend.score(trajectory, case.shot, k, samples)
    if case.mirrored and "seeded" in modes:
        # datapack/README.md, simultaneous events: taken in entity order, so the mirrored table is
        # summoned in the same order as the original (ball 9 where ball 2 was, 2 where 9 was)
        start = {i: trajectory.start[trajectory.ids.index(i)] for i in trajectory.summoned}
        balls = {i: (int(s[X]), W - int(s[Z])) for i, s in start.items()}
        mirrored, overflows = _play(emu, balls, mirror(case.shot))
        samples["overflow"].append(float(overflows))
        if mirrored.trajectory is not None:
            samples["symmetry"].append(symmetry(trajectory, mirrored.trajectory))
    if paths:
        result.paths = {"ids": trajectory.ids, "int": trajectory.positions_mm(), "seeded": seeded_paths,
                        "end-to-end": e2e_paths, "events": [e.to_json(trajectory.ids) for e in trajectory.events]}


def symmetry(shot, mirrored) -> float:
    """The largest difference, in the pack's units, between a shot and its mirror image (z -> W - z)
    over their complete ticks: positions, and velocities with vz reversed. Balls are matched by
    where they started."""
    start = {(int(s[X]), int(s[Z])): j for j, s in enumerate(mirrored.start)}
    pairs = [(i, start.get((int(s[X]), W - int(s[Z])))) for i, s in enumerate(shot.start)]
    if any(j is None for _, j in pairs) or len(shot.ticks) != len(mirrored.ticks):
        return float("inf")
    worst = 0
    for a, b in zip(shot.ticks, mirrored.ticks):
        for i, j in pairs:
            worst = max(worst, abs(a[i, X] - b[j, X]), abs(a[i, Z] - (W - b[j, Z])), abs(a[i, VX] - b[j, VX]),
                        abs(a[i, VZ] + b[j, VZ]))
    return float(worst)
