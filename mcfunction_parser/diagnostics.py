"""Source locations and diagnostics shared by the parser, the pack loader, the linter and the emulator."""
from __future__ import annotations

import functools
from collections import namedtuple
from dataclasses import dataclass

from .pack.versions import parse_mc_version, releases_label

ERROR = "error"
WARNING = "warning"
INFO = "info"


class Loc(namedtuple("Loc", ("path", "line", "col"))):
    """A position in a source file. ``line`` and ``col`` are 1-based; ``col`` counts characters.

    A named tuple, not a dataclass like the AST's nodes: the parser builds several per command,
    and a tuple is built by one C call (``new_loc``), about a third faster than a slotted object."""

    __slots__ = ()

    def __str__(self) -> str:
        return f"{self.path}:{self.line}:{self.col}"

    @staticmethod
    def new(path: str, line: int, col: int) -> "Loc":
        return new_loc((path, line, col))


# new_loc((path, line, col)) is Loc(path, line, col) built by one C call, without a Python frame
# (the parser's hot paths build locations so)
new_loc = functools.partial(tuple.__new__, Loc)


@dataclass(frozen=True, slots=True)
class Diagnostic:
    """One problem found in a pack. ``loc`` is None for problems without a position (a missing file)."""

    severity: str
    message: str
    path: str
    line: int | None = None
    col: int | None = None
    source_line: str | None = None
    versions: tuple[str, ...] | None = None  # checked over several releases: those it holds in, when not all

    @classmethod
    def at(cls, severity: str, message: str, loc: Loc, source_line: str | None = None) -> "Diagnostic":
        return cls(severity, message, loc.path, loc.line, loc.col, source_line)

    def format(self) -> str:
        """``path:line:col: error: message`` then the source line with a caret under the column."""
        where = self.path
        if self.line is not None:
            where += f":{self.line}"
            if self.col is not None:
                where += f":{self.col}"
        text = f"{where}: {self.severity}: {self.message}"
        if self.versions is not None:
            text += f" (only in {releases_label([parse_mc_version(v) for v in self.versions])})"
        if self.source_line is not None and self.col is not None:
            shown, caret_col = _clip(self.source_line, self.col)
            text += f"\n    {shown}\n    {' ' * (caret_col - 1)}^"
        return text

    def to_json(self) -> dict:
        found = {"path": self.path, "line": self.line, "col": self.col, "message": self.message}
        if self.versions is not None:
            found["versions"] = list(self.versions)
        return found


def _clip(line: str, col: int, width: int = 120) -> tuple[str, int]:
    """Shorten very long lines around the column so a 1 MB line still prints a readable caret."""
    line = line.rstrip("\n").replace("\t", " ")
    if len(line) <= width:
        return line, col
    start = max(0, col - 1 - width // 2)
    end = min(len(line), start + width)
    prefix = "..." if start > 0 else ""
    suffix = "..." if end < len(line) else ""
    return prefix + line[start:end] + suffix, col - start + len(prefix)


from .frozen_init import speed_up_inits  # noqa: E402

speed_up_inits(globals())  # the same Diagnostic, built faster (see frozen_init)
