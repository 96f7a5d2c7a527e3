"""Every benchmark figure in one run, as a markdown table, each figure beside its target.

Usage: ``python bench/run.py [--quick] [--json FILE]`` (run with the project's venv python). The
ratios are measured side by side in this one run (the machine may be shared: the ratio of two
figures taken a few seconds apart is steadier than either figure). ``--quick`` runs fewer
iterations, ticks and shots and skips the slowest rows (a smoke test: the figures are noisier);
``--json FILE`` also writes the rows as JSON. Figures that miss their target say so.

The rows reuse the other bench modules: the VM programs and the hand-written numba loop
(``bench_vm``), the pool break (``bench_pool``, ``poolgame.shot``), the batch of random shots
(``bench_score``), the parser corpus (``corpus``, ``bench_parse``), the collection-scale check
(``bench_check_scale``), and the physics pack ``bench/physics`` written in the shape of
third-party physics packs. The
third-party emulator ``mcemu`` (PyPI) runs in a venv of its own under ``bench/.venv-mcemu``,
made on first use; it is never a dependency of dpemu.
"""
from __future__ import annotations

import argparse
import gc
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import asdict, dataclass
from pathlib import Path

BENCH = Path(__file__).resolve().parent
sys.path.insert(0, str(BENCH))

import bench_check_scale  # noqa: E402
import bench_parse  # noqa: E402
import bench_pool  # noqa: E402
import bench_score  # noqa: E402
import bench_vm  # noqa: E402
from corpus import write_corpus  # noqa: E402

PHYSICS_PACK = BENCH / "physics"
PHYSICS_BODIES = 256
MCEMU_VENV = BENCH / ".venv-mcemu"
DPEMU = Path(sys.executable).with_name("dpemu")


@dataclass
class Row:
    figure: str
    measured: str               # as printed
    target: str                 # as printed; "" when the issue sets none
    met: bool | None = None     # None: no target, or not measured
    value: float | None = None  # the number behind ``measured`` (JSON)


def _ratio_row(figure: str, ours: float, theirs: float, at_least: float) -> Row:
    ratio = ours / theirs
    return Row(figure, f"{ratio:,.2f}x" if ratio < 10 else f"{ratio:,.0f}x", f">= {at_least:,g}x",
               ratio >= at_least, ratio)


def _rate(rate: float, unit: str = "commands/s") -> str:
    return f"{rate:,.0f} {unit}"


# ---------------------------------------------------------------------------------- the VM's loops
def vm_rows(quick: bool) -> list[Row]:
    vm_iterations, ref_iterations = (5_000, 20) if quick else (50_000, 100)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        pack = bench_vm.write_pack(Path(tmp) / "pack")
        vm_seconds, vm_commands = bench_vm.timed_loop(pack, "numba", vm_iterations)
        hand_seconds, hand_scores = bench_vm.hand_loop(vm_iterations)
        same = bench_vm.loop_scores(pack, "numba", vm_iterations) == hand_scores
        vm_rate = vm_commands / vm_seconds
        rows.append(Row("scoreboard loop, VM (1,000 operations per call, per-instruction counters)", _rate(vm_rate), "",
                        value=vm_rate))
        row = _ratio_row("VM / hand-written numba loop (the same array updates)", hand_seconds, vm_seconds, 0.3)
        if not same:
            row.measured += " (the two disagree on the final scores)"
            row.met = False
        rows.append(row)
        ref_seconds, ref_commands = bench_vm.timed_loop(pack, "python", ref_iterations, repeats=1)
        rows.append(_ratio_row("VM / reference backend, scoreboard loop", vm_rate, ref_commands / ref_seconds, 200))
        entity = {}
        for backend, iterations in (("numba", vm_iterations // 10), ("python", ref_iterations * 10)):
            seconds, commands = bench_vm.timed_loop(pack, backend, iterations, loop="b:eloop",
                                                    setup=("b:setup", "b:esetup"),
                                                    repeats=3 if backend == "numba" else 1)
            entity[backend] = commands / seconds
        rows.append(_ratio_row(f"VM / reference backend, entity loop ({bench_vm.ENTITIES} markers, selectors, forks)",
                               entity["numba"], entity["python"], 50))
        ticks = 1_000 if quick else 5_000
        with tempfile.TemporaryDirectory() as small:
            trivial = {backend: _trivial_pack(Path(small) / backend) for backend in ("numba", "python")}
            tick_us = {backend: tick_overhead(trivial[backend], backend, ticks) for backend in trivial}
            one_us = {backend: tick_overhead(trivial[backend], backend, ticks, per_call=True) for backend in trivial}
        rows.append(Row("tick overhead: `tick(N)`, each tick running one command, VM (reference backend)",
                        f"{tick_us['numba']:.2f} us ({tick_us['python']:.1f} us)", "<= 2 us",
                        tick_us["numba"] <= 2, tick_us["numba"]))
        rows.append(Row("tick overhead: one `tick()` call per tick, VM (reference backend)",
                        f"{one_us['numba']:.1f} us ({one_us['python']:.1f} us)", "", value=one_us["numba"]))
        host_us, work_us = bench_vm.host_round_trip(pack)
        rows.append(Row("host round trip (`time query gametime`: VM exit, Python, resume; the command's work alone)",
                        f"{host_us:.2f} us ({work_us:.2f} us)", "<= 1 us + the command's work",
                        host_us - work_us <= 1, host_us))
        rows.append(mcemu_row(pack, vm_rate, quick))
    return rows


def tick_overhead(pack: Path, backend: str, ticks: int, per_call: bool = False) -> float:
    """Microseconds per tick of ``pack``, whose tick runs one command, run by one ``tick(ticks)``
    call (or ``per_call``: one ``tick()`` call per tick); the best of 3 runs."""
    from emulator import Emulator

    emu = Emulator(backend=backend)
    emu.load(pack)
    emu.call("t:a")
    emu.tick(10)  # the load tick, and the VM's code loaded
    best = float("inf")
    for _ in range(3):
        start = time.perf_counter()
        if per_call:
            for _ in range(ticks):
                emu.tick()
        else:
            emu.tick(ticks)
        best = min(best, time.perf_counter() - start)
    return best / ticks * 1e6


# the scoreboard loop in mcemu: its own process and venv; prints seconds and the final scores
_MCEMU = """
import contextlib, io, json, sys, time
from mcemu import Emulator
emu = Emulator()
with contextlib.redirect_stdout(io.StringIO()):
    emu.load_datapack(sys.argv[1])
    emu.execute_function("b:setup")
    emu.execute_command("scoreboard players set #i o " + sys.argv[2])
    start = time.perf_counter()
    emu.execute_function("b:loop")
    seconds = time.perf_counter() - start
scores = emu.world.scoreboards["o"]
print(json.dumps({"seconds": seconds, "#a": scores["#a"], "#b": scores["#b"]}))
"""


def _mcemu_python() -> tuple[Path | None, str]:
    """The bench venv's python with mcemu installed (made on first use), or None and why not."""
    python = MCEMU_VENV / "bin" / "python"
    if python.exists() and subprocess.run([python, "-c", "import mcemu"], capture_output=True).returncode == 0:
        return python, ""
    made = subprocess.run([sys.executable, "-m", "venv", MCEMU_VENV], capture_output=True, text=True)
    if made.returncode != 0:
        return None, "could not make its venv: " + made.stderr.strip().splitlines()[-1:][0]
    installed = subprocess.run([python, "-m", "pip", "install", "-q", "mcemu"], capture_output=True, text=True)
    if installed.returncode != 0:
        lines = [line for line in installed.stderr.splitlines() if "ERROR" in line] or ["pip failed"]
        return None, "pip install mcemu failed: " + lines[0]
    return python, ""


def mcemu_row(pack: Path, vm_rate: float, quick: bool) -> Row:
    figure = "VM / mcemu (third-party Python emulator), scoreboard loop"
    python, why = _mcemu_python()
    if python is None:
        return Row(figure, f"skipped: {why}", ">= 5,000x")
    iterations = 2 if quick else 5  # mcemu recurses in Python for each function call
    done = subprocess.run([python, "-c", _MCEMU, str(pack), str(iterations)], capture_output=True, text=True)
    if done.returncode != 0:
        return Row(figure, "skipped: mcemu failed: " + (done.stderr.strip().splitlines() or ["?"])[-1], ">= 5,000x")
    theirs = json.loads(done.stdout.strip().splitlines()[-1])
    commands = bench_vm.timed_loop(pack, "python", iterations, repeats=1)[1]  # the same run, as dpemu counts it
    row = _ratio_row(figure, vm_rate, commands / theirs["seconds"], 5000)
    if {h: theirs[h] for h in ("#a", "#b")} != bench_vm.loop_scores(pack, "python", iterations):
        row.measured += " (mcemu's final scores differ)"
    return row


# -------------------------------------------------------------------------------- the physics pack
def physics_run(backend: str, ticks: int):
    """(emulator, commands, seconds, host ops) of ``ticks`` ticks of the physics pack after its setup."""
    from emulator import Emulator

    emu = Emulator(backend=backend)
    emu.load(PHYSICS_PACK)
    emu.start()
    emu.call("phys:setup/world", arguments={"bodies": PHYSICS_BODIES})
    host_before = _host_ops(emu)
    start = time.perf_counter()
    commands = emu.tick(ticks)
    seconds = time.perf_counter() - start
    return emu, commands, seconds, _host_ops(emu) - host_before


def _host_ops(emu) -> int:
    host = emu.profile.host
    return sum(host.values()) if host is not None else 0


def physics_rows(quick: bool) -> list[Row]:
    ticks = 2 if quick else 11  # the quicksort runs on tick 1
    vm, vm_commands, vm_seconds, host = physics_run("numba", ticks)
    ref, ref_commands, ref_seconds, _ = physics_run("python", ticks)
    ratio = _ratio_row(f"VM / reference backend, physics pack ({PHYSICS_BODIES} bodies, {ticks} ticks, "
                       f"{vm_commands / ticks:,.0f} commands per tick)",
                       vm_commands / vm_seconds, ref_commands / ref_seconds, 20)
    if vm.scores() != ref.scores() or vm_commands != ref_commands:
        ratio.measured += " (the backends disagree)"
        ratio.met = False
    share = host / vm_commands * 100
    return [Row("physics pack, VM", _rate(vm_commands / vm_seconds), "", value=vm_commands / vm_seconds),
            ratio,
            Row("physics pack, host ops / commands", f"{share:.2f} % ({host:,} of {vm_commands:,})", "<= 0.5 %",
                share <= 0.5, share)]


# ------------------------------------------------------------------------------- many entities moving
TP_MARKERS = 4096


def tp_rows(quick: bool) -> list[Row]:
    """``execute as @e[tag=x] at @s run tp @s ^ ^ ^1`` over 4,096 markers, on both backends."""
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp) / "pack"
        functions = root / "data" / "e" / "function"
        functions.mkdir(parents=True)
        (root / "pack.mcmeta").write_text(json.dumps({"pack": {"pack_format": 48, "description": "markers"}}))
        (functions / "spawn.mcfunction").write_text('summon marker 0 64 0 {Tags:["x"],Rotation:[30f,10f]}\n'
                                                    * TP_MARKERS)
        (functions / "move.mcfunction").write_text("execute as @e[tag=x] at @s run tp @s ^ ^ ^1\n")
        rates, positions = {}, {}
        for backend, repeats in (("numba", 3 if quick else 10), ("python", 1)):
            from emulator import Emulator

            emu = Emulator(backend=backend)
            emu.load(root)
            emu.call("e:spawn")
            emu.call("e:move")  # the VM's code loaded
            best = float("inf")
            for i in range(repeats):
                start = time.perf_counter()
                emu.call("e:move")
                best = min(best, time.perf_counter() - start)
                if i == 0:  # both backends moved them twice
                    positions[backend] = [e["pos"] for e in emu.entities("@e[tag=x]")]
            rates[backend] = TP_MARKERS / best
    row = _ratio_row(f"VM / reference backend, `execute as @e[tag=x] at @s run tp @s ^ ^ ^1` over "
                     f"{TP_MARKERS:,} markers ({rates['numba']:,.0f} teleports/s)", rates["numba"], rates["python"], 50)
    if positions["numba"] != positions["python"]:
        row.measured += " (the backends disagree)"
        row.met = False
    return [row]


# ------------------------------------------------------------------------------------ the pool pack
BREAK_BEFORE = 2.9e6  # commands/s of the break when issue #13 was filed (21 % of its time in the VM)
BREAK_SHARE_RUNS = 5  # breaks whose share of time in the VM is measured: one break's 20 ms moves with the machine


class _VMTimer:
    """Seconds spent inside the VM's loop (``emulator.vm.loop.run``) while it is installed on ``backend``:
    it stands in for ``run`` and times the compiled entry point the backend calls (not ``run``'s
    dispatcher, whose typing of the machine's type costs about 20 us a call, more than a tick's work)."""

    def __init__(self, backend) -> None:
        self.seconds = 0.0
        self.backend = backend

    def __enter__(self):
        from emulator.vm import loop
        from emulator.vm.backend import entry_point

        self.loop = getattr(self.backend, "loop", loop)  # the loop module the backend runs (emulator.vm.variants)
        self.run = self.loop.run
        last = [None, None]  # the machine type seen last and its entry point

        def timed(address, machine_type):
            if machine_type is not last[0]:
                last[:] = machine_type, entry_point(self.run, machine_type)
            start = time.perf_counter()
            try:
                return last[1](address, machine_type)
            finally:
                self.seconds += time.perf_counter() - start

        self.loop.run = timed
        self.backend.stale = True  # it calls the run it finds when it makes its machine
        return self

    def __exit__(self, *exc) -> None:
        self.loop.run = self.run
        self.backend.stale = True


def break_in_vm() -> tuple[float, float]:
    """(seconds of the break's ticks, of them inside the VM's loop), the ticks alone timed."""
    from poolgame.shot import BREAK, new_table, strike

    emu = new_table()
    ticking = 0.0
    with _VMTimer(emu.backend) as inside:
        strike(emu, BREAK)  # through the timer: the machine it makes anew for it is made here, untimed
        inside.seconds = 0.0
        for _ in range(2000):
            start = time.perf_counter()
            emu.tick()
            ticking += time.perf_counter() - start
            if emu.score("$resting", "pool.game") == 1:
                break
    return ticking, inside.seconds


def pool_rows(quick: bool) -> list[Row]:
    from poolgame.shot import BREAK, new_table, play

    emu = new_table()
    host_before = _host_ops(emu)
    result = play(emu, BREAK)
    host = _host_ops(emu) - host_before
    commands = sum(result.commands_per_tick)
    share = statistics.median(inside / ticking for ticking, inside in (break_in_vm() for _ in range(BREAK_SHARE_RUNS)))
    rows = [Row("pool break: ticks/s", f"{result.ticks / result.seconds:,.0f} ({result.ticks} ticks in "
                f"{result.seconds:.2f} s)", "", value=result.ticks / result.seconds),
            Row("pool break: commands/s", _rate(commands / result.seconds), "", value=commands / result.seconds),
            _ratio_row(f"pool break: speed-up over the {BREAK_BEFORE / 1e6:.1f} M commands/s recorded when issue "
                       "#13 was filed", commands / result.seconds, BREAK_BEFORE, 5),
            Row(f"pool break: share of its ticks' time inside the VM's loop (median of {BREAK_SHARE_RUNS} breaks)",
                f"{share * 100:.0f} %", ">= 80 %", share >= 0.8, share),
            Row("pool break: commands per tick, mean / max", f"{result.commands_mean:,.0f} / {result.commands_max:,}",
                "max <= 5,000", result.commands_max <= bench_pool.BUDGET_MOVING, result.commands_max),
            Row("pool break: host ops", f"{host:,}", "0", host == 0, host)]
    from poolgame.score.run import open_pack

    problem = open_pack(str(bench_score.DEFAULT_PACK))  # compiled once, before the workers fork
    if problem:
        raise RuntimeError(problem)
    shots = 6 if quick else 60
    for workers in (1, 2):
        seconds, _, unfinished, wrapped = bench_score.random_shots(shots, workers, seed=1)
        rate = shots / seconds
        trouble = f" ({unfinished} not at rest, {wrapped:.0f} wrapped values)" if unfinished or wrapped else ""
        rows.append(Row(f"batch: random full shots/s, {workers} worker process{'es' if workers > 1 else ''} "
                        f"({shots} shots)", f"{rate:.2f}{trouble}",
                        f">= {bench_score.TARGET_SHOTS / bench_score.TARGET_SECONDS:.1f} (1,000 in 60 s on 2 cores)"
                        if workers == 2 else "", rate * bench_score.TARGET_SECONDS >= bench_score.TARGET_SHOTS
                        if workers == 2 else None, rate))
    return rows


# ---------------------------------------------------------------------------------------- the parser
def parser_rows(quick: bool) -> list[Row]:
    with tempfile.TemporaryDirectory() as tmp:
        write_corpus(tmp, 40_000, 0)
        sources = bench_parse.load_sources(Path(tmp))
    lines = sum(text.count("\n") for _, text in sources)
    subset = sources[: max(1, len(sources) // 8)] if quick else sources  # mecha is ~60x slower
    subset_lines = sum(text.count("\n") for _, text in subset)
    (ours, _, _), (theirs, _, _) = bench_parse.side_by_side(sources, subset, 1 if quick else 3)
    rows = [Row(f"parser: lines/s on {lines:,} lines (CPU time)", _rate(lines / ours, "lines/s"), "",
                value=lines / ours)]
    row = _ratio_row("parser / mecha" + (f" (mecha on {subset_lines:,} of the lines)" if quick else ""),
                     lines / ours, subset_lines / theirs, 60)
    rows.append(row)
    return rows


# ------------------------------------------------------------------------------ processes: time, RSS
@dataclass
class Process:
    """One whole process, as measured: wall and CPU (user + system) seconds, peak RSS in bytes."""
    wall: float
    cpu: float
    peak: int
    status: int
    last: str  # standard error's last line

    def seconds(self) -> str:
        return f"{self.cpu:.2f} s (wall {self.wall:.2f} s)"


# Forks and runs a command, then prints its wall and CPU seconds, peak RSS and status. Run in a
# process of its own: Linux counts in a child's peak RSS the memory of the process it was forked
# from (exec keeps the old image's high-water mark), so this one must stay small.
_LAUNCH = """
import json, os, sys, time
start = time.perf_counter()
pid = os.fork()
if pid == 0:
    os.execvp(sys.argv[1], sys.argv[1:])
_, status, usage = os.wait4(pid, 0)
print(json.dumps([time.perf_counter() - start, usage.ru_utime + usage.ru_stime, usage.ru_maxrss * 1024,
                  os.waitstatus_to_exitcode(status)]))
"""


def measure_process(argv: list, env: dict | None = None) -> Process:
    done = subprocess.run([sys.executable, "-c", _LAUNCH, *map(str, argv)], capture_output=True, text=True,
                          env={**os.environ, **(env or {})})
    lines = done.stdout.strip().splitlines()
    last = (done.stderr.strip().splitlines() or [""])[-1]
    if done.returncode != 0 or not lines:
        return Process(0.0, 0.0, 0, done.returncode or 1, last)
    wall, cpu, peak, status = json.loads(lines[-1])
    return Process(wall, cpu, peak, status, last)


def fastest_process(argv: list, runs: int = 5) -> Process:
    """The run of ``argv`` that took the least CPU time of ``runs``: one warm start's CPU time swings
    by a third on a shared machine, the fastest is what the code costs."""
    return min((measure_process(argv) for _ in range(runs)), key=lambda p: (p.status != 0, p.cpu))


def imports_numba(argv: list) -> bool:
    """Whether ``python -m emulator ARGV`` imports numba (``-X importtime`` lists every module)."""
    done = subprocess.run([sys.executable, "-X", "importtime", "-m", "emulator", *map(str, argv)],
                          capture_output=True, text=True)
    return any(line.rsplit("|", 1)[-1].strip() == "numba" for line in done.stderr.splitlines())


def _trivial_pack(root: Path) -> Path:
    functions = root / "data" / "t" / "function"
    functions.mkdir(parents=True)
    (root / "pack.mcmeta").write_text(json.dumps({"pack": {"pack_format": 48, "description": "trivial"}}))
    (functions / "a.mcfunction").write_text("scoreboard objectives add o dummy\nscoreboard players set #a o 1\n")
    (functions / "tick.mcfunction").write_text("scoreboard players add #a o 1\n")
    tags = root / "data" / "minecraft" / "tags" / "function"
    tags.mkdir(parents=True)
    (tags / "tick.json").write_text(json.dumps({"values": ["t:tick"]}))
    return root


def startup_rows(quick: bool) -> list[Row]:
    """Whole processes; the verdicts read their CPU time (user + system), which a shared machine
    disturbs far less than the wall time printed beside it; a warm start reads the fastest of five
    runs (:func:`fastest_process`), a trivial pack's empty-cache start the fastest of three (each with
    an empty cache of its own), the pool break's its one run."""
    with tempfile.TemporaryDirectory() as tmp:
        pack = _trivial_pack(Path(tmp) / "pack")
        run = [DPEMU, "run", pack, "--call", "t:a", "--ticks", "1"]
        vm = [*run, "--backend", "numba"]
        rows = [_no_numba_row("start-up: `dpemu --help`", ["--help"]),
                _no_numba_row("start-up: `dpemu run` of a trivial pack, `--backend python`",
                              ["run", pack, "--call", "t:a", "--backend", "python"])]
        empty = min((measure_process(vm, {"NUMBA_CACHE_DIR": str(Path(tmp) / f"numba-cache-{i}")}) for i in range(3)),
                    key=lambda p: (p.status != 0, p.cpu))  # each run with a cache of its own, empty
        rows.append(_seconds_row("start-up: `dpemu run` of a trivial pack, `--backend numba`, empty numba cache",
                                 empty, 3.0, f", {empty.peak / 2**20:,.0f} MB"))
        measure_process(vm)  # the default cache, warm from here on
        rows.append(_seconds_row("start-up: `dpemu run` of a trivial pack, `--backend numba`, warm cache",
                                 fastest_process(vm), None))
        default = fastest_process(run)
        numba = imports_numba(run[1:])
        rows.append(_seconds_row("start-up: `dpemu run` of a trivial pack as a user runs it (the default backend, "
                                 "auto), warm cache", default, 0.3, ", imports numba" if numba else ", no numba"))
        shot = [DPEMU, "shot", "--break"]
        if quick:
            rows.append(Row("start-up: `dpemu shot --break`, empty numba cache", "skipped (--quick)", ""))
        else:
            cold = measure_process(shot, {"NUMBA_CACHE_DIR": str(Path(tmp) / "shot-cache")})
            rows.append(_seconds_row("start-up: `dpemu shot --break`, empty numba cache (whole process)", cold, None))
        warm = measure_process(shot)
        rows.append(_seconds_row("start-up: `dpemu shot --break`, warm cache (whole process)", warm, None))
        rows.append(Row("memory: peak RSS of `dpemu shot --break`", f"{warm.peak / 2**20:,.0f} MB", "",
                        value=warm.peak))
    return rows


def _no_numba_row(figure: str, argv: list) -> Row:
    measured = fastest_process([DPEMU, *argv])
    numba = imports_numba(argv)
    return Row(figure, measured.seconds() + (", imports numba" if numba else ", no numba"), "no numba",
               not numba and measured.status == 0, measured.cpu)


def _seconds_row(figure: str, measured: Process, at_most: float | None, extra: str = "") -> Row:
    target = f"<= {at_most:g} s" if at_most else ""
    if measured.status != 0:
        return Row(figure, f"failed (exit {measured.status}: {measured.last})", target, False)
    return Row(figure, measured.seconds() + extra, target, measured.cpu <= at_most if at_most else None,
               measured.cpu)


# ------------------------------------------------------------------------------------------ memory
_ENTITIES = """
import json, sys, time
from emulator import Emulator
emu = Emulator()
emu.load(sys.argv[1])
start = time.perf_counter()
emu.call("e:spawn")
peak = next(int(line.split()[1]) * 1024 for line in open("/proc/self/status") if line.startswith("VmHWM"))
print(json.dumps({"seconds": time.perf_counter() - start, "entities": len(emu.entities("@e")), "peak": peak}))
"""


def memory_rows(quick: bool) -> list[Row]:
    rows = []
    scale = bench_check_scale
    packs, lines = (10, 10_000) if quick else (100, scale.LINES_PER_PACK)
    with tempfile.TemporaryDirectory() as tmp:
        made = [str(p) for p in scale.write_packs(Path(tmp) / "check", packs, lines)]
        check = scale.run_child(scale.CHECK_SCRIPT, made)
        enough = quick or check["commands"] >= scale.TARGET_COMMANDS  # --quick checks a tenth
        rows.append(Row(f"memory: peak RSS of `dpemu check`, {packs} packs, {check['commands']:,} commands",
                        f"{check['peak'] / 2**30:.2f} GB in {check['seconds']:.1f} s",
                        ("" if quick else f">= {scale.TARGET_COMMANDS:,} commands, ")
                        + f"<= {scale.TARGET_GB:g} GB, <= {scale.TARGET_SECONDS:g} s",
                        enough and check["peak"] <= scale.TARGET_GB * 2**30
                        and check["seconds"] <= scale.TARGET_SECONDS, check["peak"]))
        rows.append(entities_row(Path(tmp) / "entities", 30 if quick else 60))
    return rows


def entities_row(root: Path, timeout: float, count: int = 4096) -> Row:
    functions = root / "data" / "e" / "function"
    functions.mkdir(parents=True)
    (root / "pack.mcmeta").write_text(json.dumps({"pack": {"pack_format": 48, "description": "entities"}}))
    (functions / "spawn.mcfunction").write_text('summon marker 0 64 0 {Tags:["x","y"]}\n' * count)
    figure = f"memory: peak RSS with {count:,} entities (VM, summoned by one function)"
    try:
        done = subprocess.run([sys.executable, "-c", _ENTITIES, str(root)], capture_output=True, text=True,
                              timeout=timeout)
    except subprocess.TimeoutExpired:
        return Row(figure, f"not measured: summoning them took over {timeout:g} s", "")
    if done.returncode != 0:
        return Row(figure, "failed: " + (done.stderr.strip().splitlines() or ["?"])[-1], "", False)
    found = json.loads(done.stdout.strip().splitlines()[-1])
    return Row(figure, f"{found['peak'] / 2**20:,.0f} MB (summoned in {found['seconds']:.1f} s)", "",
               value=found["peak"])


# ----------------------------------------------------------------------------------------- the table
SECTIONS = {"vm": vm_rows, "physics": physics_rows, "tp": tp_rows, "pool": pool_rows, "parser": parser_rows,
            "startup": startup_rows, "memory": memory_rows}


def machine() -> str:
    cpu = next((line.split(":", 1)[1].strip() for line in Path("/proc/cpuinfo").read_text().splitlines()
                if line.startswith("model name")), platform.processor()) if Path("/proc/cpuinfo").exists() \
        else platform.processor()
    memory = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") / 2**30
    import numba

    return (f"{cpu}, {os.cpu_count()} cores, {memory:.0f} GB; {platform.system()} {platform.release()}; "
            f"Python {platform.python_version()}, numba {numba.__version__}"
            + ("; NUMBA_BOUNDSCHECK=1" if os.environ.get("NUMBA_BOUNDSCHECK") == "1" else ""))


def _status(row: Row) -> str:
    return {True: "yes", False: "**no**", None: ""}[row.met]


def table(rows: list[Row]) -> str:
    lines = ["| figure | measured | target | met |", "|---|---|---|---|"]
    lines += [f"| {r.figure} | {r.measured} | {r.target} | {_status(r)} |" for r in rows]
    return "\n".join(lines)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer iterations, a smoke test")
    parser.add_argument("--json", type=Path, metavar="FILE", help="also write the rows as JSON")
    parser.add_argument("--only", choices=sorted(SECTIONS), action="append", help="measure only these sections")
    args = parser.parse_args()
    started = time.perf_counter()
    rows, failed = [], False
    for name in args.only or SECTIONS:
        section = SECTIONS[name]
        print(f"measuring {name}...", file=sys.stderr, flush=True)
        gc.collect()  # what the sections before left is garbage: not collected in this one's timings
        try:
            rows += section(args.quick)
        except Exception as error:  # one broken section still leaves the others' figures
            rows.append(Row(f"{name} section", f"failed: {type(error).__name__}: {error}", "", False))
            failed = True
    header = (f"Measured {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())} on {machine()}"
              f"{' (--quick)' if args.quick else ''}, in {time.perf_counter() - started:.0f} s. Ratios are of rates "
              "measured side by side in this run; start-up verdicts read the process's CPU time.")
    print(header + "\n\n" + table(rows))
    if args.json:
        args.json.write_text(json.dumps({"header": header, "quick": args.quick,
                                         "rows": [asdict(r) for r in rows]}, indent=1) + "\n")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
