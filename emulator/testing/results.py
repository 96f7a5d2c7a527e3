"""Test outcomes and the summary line."""
from __future__ import annotations

from dataclasses import dataclass, field

PASSED, FAILED, SKIPPED = "passed", "failed", "skipped"
# The test met something the emulator does not model: neither passed nor failed, with the reason.
INCONCLUSIVE = "inconclusive"


@dataclass
class TestResult:
    id: str
    path: str
    status: str
    message: str = ""
    line: int | None = None  # of the failing step (None: the whole file)
    ticks: int = 0
    seconds: float = 0.0
    optional: bool = False
    details: list[str] = field(default_factory=list)  # formatted diagnostics, runtime errors
    # the world's output lines while it ran (say, tellraw ...: LogEntry.line), the chat its `assert
    # chat` could see; a batch's tests run together, so each sees the others' lines too
    log: list[str] = field(default_factory=list)

    @property
    def where(self) -> str:
        return f"{self.path}:{self.line}" if self.line else self.path

    @property
    def counts_as(self) -> str:
        """An optional test that failed does not fail the run: it counts as skipped."""
        return SKIPPED if self.status == FAILED and self.optional else self.status

    def report(self, log: bool = False) -> str:
        """Lines for a terminal: the verdict, then where and why when it did not pass (``log``: then
        the output lines while it ran)."""
        label = {PASSED: "PASS", FAILED: "FAIL", SKIPPED: "SKIP", INCONCLUSIVE: "INCONCLUSIVE"}[self.status]
        if self.status == FAILED and self.optional:
            label = "FAIL (optional)"
        lines = [f"{label} {self.id}"]
        if self.status != PASSED:
            lines.append(f"  {self.where}: {self.message}")
        lines.extend("  " + d.replace("\n", "\n  ") for d in self.details)  # a passed test's runtime errors too
        if log:
            lines.extend("  | " + line for line in self.log)
        return "\n".join(lines)


@dataclass
class Summary:
    results: list[TestResult] = field(default_factory=list)

    def count(self, status: str) -> int:
        return sum(r.counts_as == status for r in self.results)

    @property
    def ok(self) -> bool:
        return self.count(FAILED) == 0

    def line(self) -> str:
        text = f"{self.count(PASSED)} passed, {self.count(FAILED)} failed"
        skipped, inconclusive = self.count(SKIPPED), self.count(INCONCLUSIVE)
        return text + (f", {skipped} skipped" if skipped else "") + (f", {inconclusive} inconclusive" if inconclusive else "")
