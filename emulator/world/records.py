"""What a run reports besides the world itself: log lines, runtime diagnostics with the function
traceback (frames) of each, and the sanitizer's reports of arithmetic that wrapped int32."""
from __future__ import annotations

from dataclasses import dataclass

from mcfunction_parser.diagnostics import Loc


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

    def format(self) -> str:
        where = str(self.frames[-1].loc) if self.frames else "<run>"
        lines = [f"{where}: {self.severity}: {self.message} (tick {self.tick})"]
        lines += [f"    in {f.function} at {f.loc}" for f in reversed(self.frames)]
        return "\n".join(lines)

    def to_json(self) -> dict:
        return {
            "tick": self.tick,
            "severity": self.severity,
            "message": self.message,
            "traceback": [{"function": f.function, "where": str(f.loc)} for f in self.frames],
        }


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
