"""``dpemu check`` at collection scale: many packs checked together, beside mecha on the same files.

Usage: ``python bench/bench_check_scale.py [--packs N] [--lines L] [--mecha-packs M]``. Writes N
generated packs of L lines each (bench/corpus.py, each in a namespace of its own, calling a shared
library namespace through function tags, as modules of a collection do), then, each in a fresh
process so that the peak memory is the check's own: ``dpemu check`` of all N packs together (wall
seconds, peak RSS, commands) and mecha parsing the files of the first M packs (mecha is ~30-50x
slower: its time for all N is projected from its measured lines/s, and printed as such). Targets
(issue: 100 packs / 1 M commands in <= 20 s and <= 2 GB on 2 cores) are printed beside the figures;
the default 13,000 lines a pack make 100 packs hold just over a million commands.
"""
from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from corpus import NAMESPACE, write_corpus  # noqa: E402

TARGET_SECONDS, TARGET_GB, TARGET_COMMANDS = 20.0, 2.0, 1_000_000
# lines per pack for 100 packs to hold a million commands: the corpus has about 0.77 commands a
# line (the rest are comments, blank lines and continuations)
LINES_PER_PACK = 13_000

CHECK_SCRIPT = """
import json, resource, sys, time
from mcfunction_parser.check import check_releases
def cpu():  # this process and its (finished) worker processes
    return sum(u.ru_utime + u.ru_stime for u in map(resource.getrusage, (resource.RUSAGE_SELF, resource.RUSAGE_CHILDREN)))
packs = sys.argv[1:]
start, start_cpu = time.perf_counter(), cpu()
result = check_releases(packs)
seconds, cpu_seconds = time.perf_counter() - start, cpu() - start_cpu
# this image's own peak (ru_maxrss would count the parent's, which it was forked from)
peak = next(int(line.split()[1]) * 1024 for line in open("/proc/self/status") if line.startswith("VmHWM"))
print(json.dumps({"seconds": seconds, "cpu": cpu_seconds, "peak": peak, "commands": result.commands, "lines": result.lines,
                  "errors": len(result.of("error"))}))
"""

MECHA_SCRIPT = """
import json, sys, time
from pathlib import Path
from mecha import DiagnosticError, Mecha
files = [p for root in sys.argv[1:] for p in sorted(Path(root).rglob("*.mcfunction"))]
texts = [p.read_text() for p in files]
mc = Mecha(version="1.21")
start, start_cpu = time.perf_counter(), time.process_time()
for text in texts:
    try:
        mc.parse(text, multiline=True)
    except Exception:  # DiagnosticError, and mecha's tokenizer on some inputs
        pass
print(json.dumps({"seconds": time.perf_counter() - start, "cpu": time.process_time() - start_cpu,
                  "lines": sum(t.count(chr(10)) for t in texts)}))
"""


def write_packs(root: Path, packs: int, lines: int) -> list[Path]:
    """``packs`` packs, each its own namespace (``m0``, ``m1``...)."""
    made = []
    for i in range(packs):
        dest = root / f"m{i}"
        write_corpus(dest, lines, seed=i)
        space = f"m{i}"
        (dest / "data" / NAMESPACE).rename(dest / "data" / space)
        for path in dest.rglob("*"):
            if path.is_file() and path.suffix in (".mcfunction", ".json"):
                text = path.read_text()
                path.write_text(text.replace(f"{NAMESPACE}:", f"{space}:"))
        made.append(dest)
    return made


def run_child(script: str, args: list[str]) -> dict:
    done = subprocess.run([sys.executable, "-c", script, *args], capture_output=True, text=True, check=True)
    return json.loads(done.stdout.strip().splitlines()[-1])


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--packs", type=int, default=100)
    parser.add_argument("--lines", type=int, default=LINES_PER_PACK, help="lines per pack")
    parser.add_argument("--mecha-packs", type=int, default=3, help="packs mecha parses (0: none)")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        packs = [str(p) for p in write_packs(Path(tmp), args.packs, args.lines)]
        ours = run_child(CHECK_SCRIPT, packs)
        print("| figure | measured | target |\n|---|---|---|")
        print(f"| commands checked ({args.packs} packs, {ours['lines']:,} lines) | {ours['commands']:,} | "
              f">= {TARGET_COMMANDS:,} |")
        print(f"| dpemu check of them (wall; CPU of the check and its worker processes) | {ours['seconds']:.1f} s "
              f"(CPU {ours['cpu']:.1f} s) | <= {TARGET_SECONDS:.0f} s |")
        print(f"| peak memory of that check | {ours['peak'] / 2**30:.2f} GB | <= {TARGET_GB:.0f} GB |")
        print(f"| dpemu check lines/s | {ours['lines'] / ours['seconds']:,.0f} | |")
        if args.mecha_packs:
            theirs = run_child(MECHA_SCRIPT, packs[: args.mecha_packs])
            rate, cpu_rate = theirs["lines"] / theirs["seconds"], theirs["lines"] / theirs["cpu"]
            print(f"| mecha lines/s ({args.mecha_packs} of the packs; CPU) | {rate:,.0f} ({cpu_rate:,.0f}) | |")
            print(f"| mecha, all {args.packs} packs (projected from its lines/s; CPU) | {ours['lines'] / rate:.0f} s "
                  f"({ours['lines'] / cpu_rate:.0f} s) | |")
            print(f"| dpemu check / mecha parse speed (wall; CPU) | "
                  f"{ours['lines'] / ours['seconds'] / rate:.1f}x ({ours['lines'] / ours['cpu'] / cpu_rate:.1f}x) | |")


if __name__ == "__main__":
    main()
