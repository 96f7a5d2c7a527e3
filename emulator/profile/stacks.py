"""Call stacks for the profiler: a :class:`~emulator.runtime.backend.CallRecorder` counting the
commands charged in each call stack (root first) and the calls per function.

A backend with the call-recording hook (the reference backend) tells it every charge, so
``sum(stacks.values())`` equals the commands executed: each root's own call (charged on no line)
is counted as a one-function stack.
"""
from __future__ import annotations

from collections import Counter


class CallStacks:
    def __init__(self) -> None:
        self.stacks: Counter[tuple[str, ...]] = Counter()
        self.calls: Counter[str] = Counter()  # calls made by commands (roots not included)

    def call(self, function_id: str) -> None:
        self.calls[function_id] += 1

    def charge(self, stack: tuple[str, ...]) -> None:
        self.stacks[stack] += 1

    def totals(self, root_calls: Counter) -> dict[str, int]:
        """Inclusive cost as the VM counts it (:mod:`emulator.profile.data`): every charge counts
        once for each distinct function on its stack, except a root's own call (``root_calls``:
        the roots that made it, per function), which is on no line."""
        totals: Counter = Counter()
        for stack, count in self.stacks.items():
            for function in set(stack):
                totals[function] += count
        totals.subtract(root_calls)
        return {f: c for f, c in totals.items() if c}
