"""VM benchmark, figures side by side in one run:

- VM throughput: commands per second on a loop-heavy function (1000 scoreboard operations per
  call, called in a counted recursive loop; the per-instruction counters are always on), and with
  the overflow sanitizer on;
- the same program on the reference backend (fewer iterations) and the speed ratio;
- the first call in a new process with a warm numba cache (subprocess), minus a second call;
- the host round trip: a function of host commands (``time query gametime``), per command;
- an entity-heavy loop: 16 markers, ``execute as @e[tag=x,scores={s=0..2}] run scoreboard players
  add @s s 1`` and a selector ``set`` per iteration, on the VM (selectors, forks) and on the reference;
- the entity store at scale (``--markers N``, 4,096 by default): summoning N markers, then
  ``execute as @e[tag=x] at @s run tp @s ^ ^ ^1`` over them, on both backends (seconds and ratio).

Usage: python bench/bench_vm.py [--quick] [--baseline DIR] [--markers N] [--only-store]

``--baseline DIR`` (an export of an older commit, e.g. ``git archive REV | tar -x -C DIR``) only
compares the scoreboard loop: this tree and DIR's emulator, each in a fresh process,
alternately, reporting the medians (the machine is shared, so single runs are noisy).
"""
from __future__ import annotations

import json
import os
import statistics
import subprocess
import sys
import tempfile
import textwrap
import time
from pathlib import Path

import numpy as np
from numba import njit

BODY_OPS = 1000
# the loop body cycles through these; values stay small (every product is reduced mod #d), so the
# sanitizer path reports nothing. hand_loop below does the same updates in plain numba.
BODY_CYCLE = ("scoreboard players operation #a o += #b o", "scoreboard players operation #a o %= #d o",
              "scoreboard players operation #b o *= #c o", "scoreboard players operation #b o %= #d o",
              "scoreboard players add #a o 7",
              "execute if score #a o matches 0.. run scoreboard players remove #b o 3")
SETUP_SCORES = {"#a": 1, "#b": 3, "#c": 5, "#d": 1000003}
HOST_OPS = 2000
ENTITIES = 16


def write_pack(root: Path) -> Path:
    functions = root / "data" / "b" / "function"
    functions.mkdir(parents=True)
    (root / "pack.mcmeta").write_text(json.dumps({"pack": {"pack_format": 48, "description": "bench"}}))
    body = "\n".join(BODY_CYCLE[i % len(BODY_CYCLE)] for i in range(BODY_OPS))
    (functions / "setup.mcfunction").write_text(
        "scoreboard objectives add o dummy\ngamerule maxCommandChainLength 2147483647\n"
        + "".join(f"scoreboard players set {holder} o {value}\n" for holder, value in SETUP_SCORES.items()))
    (functions / "body.mcfunction").write_text(body + "\n")
    (functions / "loop.mcfunction").write_text(
        "function b:body\nscoreboard players remove #i o 1\nexecute if score #i o matches 1.. run function b:loop\n")
    (functions / "host.mcfunction").write_text("time query gametime\n" * HOST_OPS)
    (functions / "esetup.mcfunction").write_text(
        "scoreboard objectives add s dummy\n" + 'summon marker 0 0 0 {Tags:["x"]}\n' * ENTITIES
        + "scoreboard players set @e[tag=x] s 0\n")
    (functions / "summon.mcfunction").write_text('summon marker 0 0 0 {Tags:["x"]}\n')
    (functions / "summon_n.mcfunction").write_text(
        "function b:summon\nscoreboard players remove #n o 1\nexecute if score #n o matches 1.. run function b:summon_n\n")
    (functions / "walk.mcfunction").write_text("execute as @e[tag=x] at @s run tp @s ^ ^ ^1\n")
    (functions / "eloop.mcfunction").write_text(
        "execute as @e[tag=x,scores={s=0..2}] run scoreboard players add @s s 1\n"
        "scoreboard players set @e[tag=x,scores={s=3..}] s 0\n"
        "scoreboard players remove #i o 1\nexecute if score #i o matches 1.. run function b:eloop\n")
    return root


def timed_loop(pack: Path, backend: str, iterations: int, sanitize: bool = False,
               repeats: int = 3, loop: str = "b:loop", setup: tuple[str, ...] = ("b:setup",)) -> tuple[float, int]:
    """(seconds, commands) of one root running the loop ``iterations`` times, after a warm-up;
    the best of ``repeats`` runs, since the machine is shared."""
    from emulator import Emulator

    emu = Emulator(backend=backend, sanitize=sanitize)
    emu.load(pack)
    for function in setup:
        emu.call(function)
    emu.set_score("#i", "o", 1)
    emu.call(loop)  # warm-up: JIT compilation or cache load
    best = float("inf")
    for _ in range(repeats):
        emu.set_score("#i", "o", iterations)
        start = time.perf_counter()
        result = emu.runtime.call(loop)
        best = min(best, time.perf_counter() - start)
    return best, result.cost


@njit(cache=True)
def _hand_loop(s, cycles, rest):
    """The scoreboard loop's updates written by hand over an int32 array (``s[0..4]``: #a #b #c #d
    #i): ``cycles`` times BODY_CYCLE, then its first ``rest`` commands, per iteration; the practical
    limit of a VM running that program. int32 stores wrap as Java's int arithmetic does, and ``%``
    with a positive divisor is the game's floorMod."""
    while True:
        for _ in range(cycles):
            s[0] = s[0] + s[1]
            s[0] = s[0] % s[3]
            s[1] = s[1] * s[2]
            s[1] = s[1] % s[3]
            s[0] = s[0] + 7
            if s[0] >= 0:
                s[1] = s[1] - 3
        if rest > 0:
            s[0] = s[0] + s[1]
        if rest > 1:
            s[0] = s[0] % s[3]
        if rest > 2:
            s[1] = s[1] * s[2]
        if rest > 3:
            s[1] = s[1] % s[3]
        if rest > 4:
            s[0] = s[0] + 7
        s[4] = s[4] - 1
        if s[4] < 1:
            return


def hand_loop(iterations: int, repeats: int = 3) -> tuple[float, dict[str, int]]:
    """(best seconds, final #a #b) of the hand-written loop running ``iterations`` times, after a
    warm-up; the same updates as ``timed_loop(pack, ..., iterations)``."""
    start_values = [SETUP_SCORES["#a"], SETUP_SCORES["#b"], SETUP_SCORES["#c"], SETUP_SCORES["#d"], 1]
    cycles, rest = divmod(BODY_OPS, len(BODY_CYCLE))
    _hand_loop(np.array(start_values, dtype=np.int32), cycles, rest)
    best, s = float("inf"), None
    for _ in range(repeats):
        s = np.array(start_values[:4] + [iterations], dtype=np.int32)
        start = time.perf_counter()
        _hand_loop(s, cycles, rest)
        best = min(best, time.perf_counter() - start)
    return best, {"#a": int(s[0]), "#b": int(s[1])}


def loop_scores(pack: Path, backend: str, iterations: int) -> dict[str, int]:
    """#a and #b after the setup and one run of the loop ``iterations`` times (hand_loop's check)."""
    from emulator import Emulator

    emu = Emulator(backend=backend)
    emu.load(pack)
    emu.call("b:setup")
    emu.set_score("#i", "o", iterations)
    emu.call("b:loop")
    return {holder: emu.score(holder, "o") for holder in ("#a", "#b")}


def host_round_trip(pack: Path) -> tuple[float, float]:
    """Microseconds per host command, VM exit and resume included, and of the command's own work
    (the host running the same command as often, without the VM); the best of three each."""
    from emulator import Emulator
    from emulator.world.context import Context

    emu = Emulator()
    emu.load(pack)
    emu.call("b:setup")
    emu.call("b:host")
    trip = work = float("inf")
    backend = emu.backend
    node = next(op.node for op in backend.program.host_ops if op.function == "b:host")
    for _ in range(3):
        start = time.perf_counter()
        emu.call("b:host")
        trip = min(trip, time.perf_counter() - start)
        start = time.perf_counter()
        for _ in range(HOST_OPS):
            backend.host.run_final(node, Context())
        work = min(work, time.perf_counter() - start)
    return trip / HOST_OPS * 1e6, work / HOST_OPS * 1e6


def entity_store(pack: Path, backend: str, markers: int) -> tuple[float, float, int]:
    """(seconds to summon ``markers`` markers in one root, seconds of a ``walk`` over them, its commands)."""
    from emulator import Emulator

    emu = Emulator(backend=backend)
    emu.load(pack)
    emu.call("b:setup")
    emu.set_score("#n", "o", 1)
    emu.call("b:summon_n")  # warm-up (compilation, cache)
    emu.call("b:walk")
    emu.set_score("#n", "o", markers - 1)
    start = time.perf_counter()
    emu.runtime.call("b:summon_n")
    summoned = time.perf_counter() - start
    best = float("inf")
    for _ in range(3):  # the best of three walks (the machine is shared)
        start = time.perf_counter()
        result = emu.runtime.call("b:walk")
        best = min(best, time.perf_counter() - start)
    return summoned, best, result.cost


def store_rows(pack: Path, markers: int) -> None:
    rows = {backend: entity_store(pack, backend, markers) for backend in ("numba", "python")}
    (vs, vw, vn), (rs, rw, rn) = rows["numba"], rows["python"]
    print(f"summon {markers:,} markers: VM {vs:.3f} s, reference {rs:.3f} s; VM / reference speed {rs / vs:.2f}x")
    print(f"execute as @e[tag=x] at @s run tp @s ^ ^ ^1 over {markers:,} markers: VM {vn / vw:,.0f} commands/s, "
          f"reference {rn / rw:,.0f} commands/s; VM / reference speed {(vn / vw) / (rn / rw):.2f}x")


def first_call_overhead(pack: Path) -> tuple[float, float]:
    """(first call, second call) seconds in a fresh process, after a run that warmed the cache.
    The first call pays for loading the VM's machine code from numba's cache."""
    script = textwrap.dedent(f"""
        import time
        from emulator import Emulator
        emu = Emulator(); emu.load({str(pack)!r})
        t0 = time.perf_counter(); emu.call("b:setup"); t1 = time.perf_counter(); emu.call("b:setup")
        t2 = time.perf_counter()
        print(t1 - t0, t2 - t1)
    """)
    subprocess.run([sys.executable, "-c", script], check=True, capture_output=True)  # warm the cache
    out = subprocess.run([sys.executable, "-c", script], check=True, capture_output=True, text=True).stdout
    first, second = (float(x) for x in out.split())
    return first, second


def loop_rate_in(tree: Path, iterations: int) -> float:
    """Commands per second of the scoreboard loop, run by ``tree``'s emulator in a new
    process (this file's pack and timing; the tree comes first on the import path)."""
    script = textwrap.dedent(f"""
        import importlib.util, tempfile
        from pathlib import Path
        spec = importlib.util.spec_from_file_location("bench_vm", {__file__!r})
        bench = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(bench)
        with tempfile.TemporaryDirectory() as tmp:
            seconds, commands = bench.timed_loop(bench.write_pack(Path(tmp) / "pack"), "numba", {iterations}, repeats=5)
        print(commands / seconds)
    """)
    env = dict(os.environ, PYTHONPATH=str(tree))  # run in the tree: `python -c` puts the working folder first
    return float(subprocess.run([sys.executable, "-c", script], check=True, capture_output=True, text=True,
                                env=env, cwd=tree).stdout)


def compare_with(baseline: Path, rounds: int, iterations: int) -> None:
    """This tree's scoreboard loop against ``baseline``'s, alternating, medians of ``rounds`` runs each."""
    here = Path(__file__).resolve().parents[1]
    rates: dict[Path, list[float]] = {here: [], baseline: []}
    for _ in range(rounds):
        for tree in (baseline, here):
            rates[tree].append(loop_rate_in(tree, iterations))
    now, before = statistics.median(rates[here]), statistics.median(rates[baseline])
    print(f"scoreboard loop (median of {rounds} runs each, best of 5 inside a run)")
    for name, tree in (("this tree", here), (str(baseline), baseline)):
        print(f"  {name:<28}{statistics.median(rates[tree]):>16,.0f} commands/s   runs: "
              + ", ".join(f"{r / 1e6:.0f}M" for r in rates[tree]))
    print(f"this tree / baseline: {now / before:.3f}")


def main() -> None:
    quick = "--quick" in sys.argv
    if "--baseline" in sys.argv:
        compare_with(Path(sys.argv[sys.argv.index("--baseline") + 1]).resolve(), 3 if quick else 5,
                     5_000 if quick else 50_000)
        return
    markers = int(sys.argv[sys.argv.index("--markers") + 1]) if "--markers" in sys.argv else 4096
    if "--only-store" in sys.argv:
        with tempfile.TemporaryDirectory() as tmp:
            store_rows(write_pack(Path(tmp) / "pack"), markers)
        return
    vm_iterations = 5_000 if quick else 50_000
    ref_iterations = 20 if quick else 100
    with tempfile.TemporaryDirectory() as tmp:
        pack = write_pack(Path(tmp) / "pack")
        rows = []
        t, n = timed_loop(pack, "numba", vm_iterations)
        vm_rate = n / t
        rows.append(("VM", n, t, vm_rate))
        t, n = timed_loop(pack, "numba", vm_iterations, sanitize=True)
        rows.append(("VM, sanitizer on", n, t, n / t))
        t, n = timed_loop(pack, "python", ref_iterations, repeats=1)
        ref_rate = n / t
        rows.append(("reference backend", n, t, ref_rate))
        entity_rows = []
        for backend, iterations in (("numba", vm_iterations // 10), ("python", ref_iterations * 10)):
            t, n = timed_loop(pack, backend, iterations, loop="b:eloop", setup=("b:setup", "b:esetup"),
                              repeats=3 if backend == "numba" else 1)
            entity_rows.append((f"entities, {'VM' if backend == 'numba' else 'reference'}", n, t, n / t))
        host_us, work_us = host_round_trip(pack)
        first, second = first_call_overhead(pack)
        store_rows(pack, markers)

    print(f"{'run':<22}{'commands':>14}{'seconds':>10}{'commands/s':>16}")
    for name, n, t, rate in rows:
        print(f"{name:<22}{n:>14,}{t:>10.3f}{rate:>16,.0f}")
    print(f"VM / reference speed: {vm_rate / ref_rate:,.0f}x")
    for name, n, t, rate in entity_rows:
        print(f"{name:<22}{n:>14,}{t:>10.3f}{rate:>16,.0f}")
    print(f"entities: VM / reference speed: {entity_rows[0][3] / entity_rows[1][3]:,.1f}x")
    print(f"host command round trip: {host_us:.2f} us per command (VM exit, Python handler, resume; the "
          f"command's work alone {work_us:.2f} us)")
    print(f"first call in a new process (warm cache): {first:.3f} s; second call {second * 1e3:.2f} ms; "
          f"added {first - second:.3f} s")


if __name__ == "__main__":
    main()
