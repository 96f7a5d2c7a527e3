"""Folding execution counters into a profile: per source line, per function (self and total),
per tick.

``self`` of a function is the cost charged by its own commands (a ``function`` call's own charge
belongs to the calling line; a root's own call is on no line); ``total`` adds its callees,
counted once per outermost activation (numba backend only). Macro instances (``ns:f#3``) fold into their function.
"""
from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field


@dataclass
class Profile:
    lines: dict[tuple[str, int], int] = field(default_factory=dict)  # (path, line) -> commands
    functions_self: dict[str, int] = field(default_factory=dict)
    functions_total: dict[str, int] = field(default_factory=dict)
    ticks: list[int] = field(default_factory=list)  # commands per tick

    def top_lines(self, n: int = 20) -> list[tuple[tuple[str, int], int]]:
        return sorted(self.lines.items(), key=lambda kv: -kv[1])[:n]

    def to_json(self) -> dict:
        return {
            "lines": [{"path": p, "line": line, "commands": c} for (p, line), c in self.top_lines(len(self.lines))],
            "functions": [
                {"function": f, "self": c, "total": self.functions_total.get(f)}
                for f, c in sorted(self.functions_self.items(), key=lambda kv: -kv[1])
            ],
            "ticks": self.ticks,
        }


def base_function(function_id: str) -> str:
    return function_id.split("#", 1)[0]


def fold(line_counts: dict[tuple[str, int], int], function_paths: dict[str, str],
         totals: dict[str, int] | None = None, ticks: list[int] | None = None) -> Profile:
    """Build a :class:`Profile` from per-line counts; ``function_paths`` maps a source path to its
    function id, ``totals`` (function -> inclusive cost) when the backend tracks them."""
    functions_self: Counter = Counter()
    for (path, _line), count in line_counts.items():
        functions_self[function_paths.get(path, path)] += count
    folded_totals: Counter = Counter()
    for function, cost in (totals or {}).items():
        folded_totals[base_function(function)] += cost
    return Profile(dict(line_counts), dict(functions_self), dict(folded_totals), list(ticks or []))
