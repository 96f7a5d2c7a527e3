"""Profile writers (table, json, collapsed stacks, the game's ``/debug function`` trace) and the
comparison with a saved JSON baseline.

The report they write is a plain dict built by :mod:`emulator.cli.profile`::

    {"backend", "limit", "commands", "ticks": {"count", "mean", "max", "series"},
     "roots": [{"function", "runs", "max_cost", "mean_cost", "headroom", "cut"}],
     "functions": [{"function", "self", "total", "calls"}],
     "lines": [{"path", "line", "commands", "source", "instructions": [{"op", "count"}]}] (op: the
         VM instruction's name in emulator.vm.opcodes, as ``dpemu disasm`` prints it),
     "host": [{"function", "path", "line", "op", "command", "count"}] (None on the python backend):
         every host op Python ran, op being "command" (a final command), "stage" (an execute
         stage) or "store" (an execute store), count the times it ran,
     "stacks": {"a;b;c": count} (when recorded)}
"""
from __future__ import annotations

import io
import json

FORMATS = ("table", "json", "collapsed", "trace")
DEFAULT_THRESHOLD = 10.0  # percent


# ---------------------------------------------------------------------- the /debug function trace
class TraceWriter:
    """The game's trace format (DebugCommand.Tracer, 1.20.3+): per traced root its id, then
    ``[F] id size=N`` per call, ``[C] command`` per command line, its result appended as
    `` -> N`` or, when something came in between, ``[R = N] command`` on its own line; each line
    indented 4 spaces per depth plus one; ``[E] message`` for a command that failed."""

    def __init__(self) -> None:
        self.out = io.StringIO()
        self.waiting = False  # a [C] line waits for its result
        self.last_depth = 0

    def _indent(self, depth: int) -> None:
        self.out.write("    " * (depth + 1))
        self.last_depth = depth

    def _end_line(self) -> None:
        if self.waiting:
            self.out.write("\n")
            self.waiting = False

    def root(self, function_id: str) -> None:
        self._end_line()
        self.out.write(function_id + "\n")

    def call(self, depth: int, function_id: str, size: int) -> None:
        self._end_line()
        self._indent(depth)
        self.out.write(f"[F] {function_id} size={size}\n")

    def command(self, depth: int, text: str) -> None:
        self._end_line()
        self._indent(depth)
        self.out.write(f"[C] {text}")
        self.waiting = True

    def result(self, depth: int, text: str, value: int) -> None:
        if self.waiting:
            self.out.write(f" -> {value}\n")
            self.waiting = False
        else:
            self._indent(depth)
            self.out.write(f"[R = {value}] {text}\n")

    def error(self, message: str) -> None:
        """``[E] message`` one level deeper than the last line; like the game's Tracer.onError, it
        ends no line, so what follows continues on it."""
        self._end_line()
        self._indent(self.last_depth + 1)
        self.out.write(f"[E] {message}")

    def text(self) -> str:
        self._end_line()
        return self.out.getvalue()


# ---------------------------------------------------------------------- writers
def write_json(report: dict) -> str:
    return json.dumps(report, indent=1) + "\n"


def write_collapsed(report: dict) -> str:
    """Folded stacks, ``root;caller;callee COUNT`` per line (flamegraph.pl, speedscope)."""
    stacks = report.get("stacks") or {}
    return "".join(f"{stack} {count}\n" for stack, count in sorted(stacks.items()))


def parse_collapsed(text: str) -> dict[str, int]:
    out: dict[str, int] = {}
    for line in text.splitlines():
        stack, _, count = line.rpartition(" ")
        out[stack] = out.get(stack, 0) + int(count)
    return out


def write_table(report: dict, top: int) -> str:
    t = report["ticks"]
    lines = [
        f"backend {report['backend']}: {report['commands']} commands, {t['count']} ticks "
        f"(mean {t['mean']:.1f}, max {t['max']} per tick)",
    ]
    outside = report.get("outside_ticks")
    if outside:
        lines.append(f"outside ticks: load {outside['load']}, --set/--call {outside['setup']}")
    if t["series"]:
        shown = " ".join(str(c) for c in t["series"][:top])
        lines.append(f"per tick: {shown}{' ...' if len(t['series']) > top else ''}")
    lines += ["", f"roots (quota {report['limit']} each):",
              f"{'runs':>8} {'max':>8} {'mean':>10} {'headroom':>9} {'cut':>4}  function"]
    for r in report["roots"]:
        lines.append(f"{r['runs']:>8} {r['max_cost']:>8} {r['mean_cost']:>10.1f} {r['headroom']:>9} {r['cut']:>4}  "
                     f"{r['function']}")
    lines += ["", f"functions (top {top} by total):", f"{'self':>10} {'total':>10} {'calls':>8}  function"]
    for f in report["functions"][:top]:
        lines.append(f"{f['self']:>10} {_opt(f['total']):>10} {_opt(f['calls']):>8}  {f['function']}")
    lines += ["", f"hot lines (top {top}):"]
    for entry in report["lines"][:top]:
        ops = ", ".join(f"{i['op']} {i['count']}" for i in entry.get("instructions", []))
        lines.append(f"{entry['commands']:>10}  {entry['path']}:{entry['line']}  {entry['source']}")
        if ops:
            lines.append(f"{'':>12}[{ops}]")
    host = report["host"]
    if host is None:
        lines += ["", "host-executed commands: n/a (the python backend runs every command in Python)"]
    else:
        lines += ["", f"host-executed commands ({len(host)}, top {top}):" if host else "host-executed commands: none"]
    for h in (host or [])[:top]:
        lines.append(f"{h['count']:>10}  {h['function']}  {h['path']}:{h['line']}  {h['op']}  {h['command']}")
    return "\n".join(lines) + "\n"


def _opt(value) -> str:
    return "-" if value is None else str(value)


# ---------------------------------------------------------------------- baseline
def function_costs(report: dict) -> dict[str, int]:
    """The count compared per function: inclusive (total) when known, else self."""
    return {f["function"]: f["total"] if f.get("total") is not None else f["self"] for f in report["functions"]}


def compare(baseline: dict, report: dict, threshold: float) -> list[str]:
    """A line per function whose count grew by more than ``threshold`` percent (a function
    absent from the baseline counts from 0); empty when none did."""
    before, after = function_costs(baseline), function_costs(report)
    out = []
    for function, now in sorted(after.items()):
        was = before.get(function, 0)
        if now > was and (was == 0 or (now - was) * 100 > threshold * was):
            growth = "new" if was == 0 else f"+{(now - was) * 100 / was:.1f}%"
            out.append(f"{function}: {was} -> {now} ({growth}, threshold {threshold:g}%)")
    return out
