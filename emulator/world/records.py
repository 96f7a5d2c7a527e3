"""What a run reports besides the world itself: log lines, runtime diagnostics with the function
traceback (frames) of each, and the sanitizer's reports of arithmetic that wrapped int32."""
from __future__ import annotations

from dataclasses import dataclass

from mcfunction_parser.diagnostics import Loc
from emulator.world.text import plain_text


@dataclass(frozen=True, slots=True)
class LogEntry:
    """One line of output: ``kind`` is ``"say"``, ``"tellraw"``, ``"chat"`` (a system message such
    as ``random roll``'s), ``"info"`` (e.g. the quota cut
    message "Command execution stopped due to limit") or ``"error"`` (a failed command's message)."""

    tick: int
    kind: str
    text: str
    loc: Loc | None = None
    receivers: tuple[str, ...] = ()  # UUIDs (Java strings) of the players the message was sent to

    def to_json(self) -> dict:
        return {"tick": self.tick, "kind": self.kind, "text": self.text, "where": str(self.loc) if self.loc else None}

    def read_text(self, release=None) -> str:
        """What a player reads of the line: a tellraw's component as plain text (translated as in
        ``release``: :func:`emulator.world.text.plain_text`), others as logged."""
        return plain_text(self.text, release) if self.kind == "tellraw" else self.text

    def line(self, release=None) -> str:
        """The line for a terminal: its tick, kind, text as read and where the command stands."""
        where = f"  ({self.loc})" if self.loc else ""
        return f"tick {self.tick} {self.kind}: {self.read_text(release)}{where}"


@dataclass(frozen=True, slots=True)
class Frame:
    """One function on the call stack at the time of a runtime error; ``loc`` is the command
    being run in it (for the innermost frame: the failing command)."""

    function: str
    loc: Loc


@dataclass(frozen=True, slots=True)
class RuntimeDiagnostic:
    """A run-time problem (unknown function, stack overflow, quota cut, missing macro key,
    division by zero ...). ``frames`` go from the root (outermost) to the failing command."""

    tick: int
    message: str
    frames: tuple[Frame, ...] = ()
    severity: str = "error"
    # something the emulator does not model was met (a test seeing one is inconclusive)
    unmodelled: bool = False

    def format(self) -> str:
        where = str(self.frames[-1].loc) if self.frames else "<run>"
        lines = [f"{where}: {self.severity}: {self.message} (tick {self.tick})"]
        for item in folded(tuple(reversed(self.frames))):
            if isinstance(item, Frame):
                lines.append(f"    in {item.function} at {item.loc}")
            else:
                lines.append(f"    ... {item.count:,} more frames of {' -> '.join(item.functions)}")
        return "\n".join(lines)

    def to_json(self) -> dict:
        return {
            "tick": self.tick,
            "severity": self.severity,
            "message": self.message,
            "unmodelled": self.unmodelled,
            "traceback": [{"function": i.function, "where": str(i.loc)} if isinstance(i, Frame)
                          else {"folded": i.count, "functions": list(i.functions)}
                          for i in folded(tuple(reversed(self.frames)))],
        }


@dataclass(frozen=True, slots=True)
class Folded:
    """``count`` frames left out of a traceback: a cycle of ``functions`` calling each other again."""

    count: int
    functions: tuple[str, ...]


_LONGEST_CYCLE = 4  # calls that repeat with a longer period are shown as they are


def folded(frames: tuple[Frame, ...]) -> list:
    """``frames`` (innermost first) with each run of a repeating cycle (a function calling itself,
    or two to four calling each other) kept once at each end and the repeats between replaced by
    one :class:`Folded`: a 32,768-deep recursion prints three lines, not 32,768."""
    out: list = []
    i = 0
    while i < len(frames):
        period, repeats = _cycle_at(frames, i)
        if repeats < 3:
            out.append(frames[i])
            i += 1
            continue
        out.extend(frames[i:i + period])
        hidden = (repeats - 2) * period
        out.append(Folded(hidden, tuple(f.function for f in frames[i:i + period])))
        last = i + (repeats - 1) * period
        out.extend(frames[last:last + period])
        i = last + period
    return out


def _cycle_at(frames: tuple[Frame, ...], start: int) -> tuple[int, int]:
    """(period, times) of the repeating block starting at ``start`` that covers most frames."""
    best = (1, 1)
    for period in range(1, _LONGEST_CYCLE + 1):
        block = frames[start:start + period]
        if len(block) < period:
            break
        times = 1
        while frames[start + times * period:start + (times + 1) * period] == block:
            times += 1
        if times * period > best[0] * best[1]:
            best = (period, times)
    return best


@dataclass(frozen=True, slots=True)
class Overflow:
    """An arithmetic result that wrapped int32 (sanitizer): ``exact`` is the unwrapped value,
    ``stored`` what the game stores. ``op`` is ``+= -= *= add remove`` ..."""

    tick: int
    function: str
    loc: Loc
    op: str
    a: int
    b: int
    exact: int
    stored: int

    def to_json(self) -> dict:
        return {
            "tick": self.tick, "function": self.function, "where": str(self.loc), "op": self.op,
            "a": self.a, "b": self.b, "exact": self.exact, "stored": self.stored,
        }
