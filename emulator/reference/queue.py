"""The command queue of one root sequence, modelled on the game's ``ExecutionContext``.

Work is a deque of entries ``(frame, action)``. Running an entry may queue new entries; they go
in front of the queue, in the order queued, once the entry returns (``pushNewCommands``), which
makes execution depth-first without any Python recursion: a 100,000-deep function chain is a
long queue, not a deep stack.

Before each entry the quota is checked (``quota <= 0`` stops the root); only
:meth:`ExecutionQueue.charge` lowers it (the cost rule is documented in :mod:`emulator.runtime.backend`).
"""
from __future__ import annotations

from collections import deque
from dataclasses import dataclass
from typing import Callable, Optional

# (success, value) -> None, the game's CommandResultCallback; None is CommandResultCallback.EMPTY.
Callback = Optional[Callable[[bool, int], None]]

MAX_QUEUE = 10_000_000  # ExecutionContext.MAX_QUEUE_DEPTH


def chain(first: Callback, second: Callback) -> Callback:
    """CommandResultCallback.chain: call ``first`` then ``second``; EMPTY (None) drops out."""
    if first is None:
        return second
    if second is None:
        return first

    def both(success: bool, value: int) -> None:
        first(success, value)
        second(success, value)

    return both


@dataclass(frozen=True, slots=True)
class CallFrame:
    """The game's ``Frame``: a function activation's depth, where its ``return`` goes, and the
    depth whose queued entries ``discard`` drops (its own, or its parent's for
    ``returnParentFrame`` calls: ``return run function``, ``execute if function``)."""

    depth: int
    on_return: Callback
    discard_depth: int

    def return_success(self, value: int) -> None:
        if self.on_return is not None:
            self.on_return(True, value)

    def return_failure(self) -> None:
        if self.on_return is not None:
            self.on_return(False, 0)


Action = Callable[["ExecutionQueue", CallFrame], None]


class ExecutionQueue:
    """One root's queue, quota and cost. Both limits are read once, when the root starts."""

    def __init__(self, limit: int, fork_limit: int, on_internal_error: Callable[[Action, Exception], None]) -> None:
        self.limit = limit
        self.fork_limit = fork_limit
        self.on_internal_error = on_internal_error
        self.quota = limit
        self.cost = 0
        self.cut = False
        self.overflowed = False
        self._queue: deque[tuple[CallFrame, Action]] = deque()
        self._new: list[tuple[CallFrame, Action]] = []

    def queue_next(self, frame: CallFrame, action: Action) -> None:
        if len(self._new) + len(self._queue) > MAX_QUEUE:
            self.overflowed = True
            self._new.clear()
            self._queue.clear()
        if not self.overflowed:
            self._new.append((frame, action))

    def charge(self) -> None:
        """``incrementCost``: one quota unit."""
        self.quota -= 1
        self.cost += 1

    def discard(self, frame: CallFrame) -> None:
        """``Frame.discard``: drop queued entries at ``frame.discard_depth`` or deeper."""
        queue = self._queue
        while queue and queue[0][0].depth >= frame.discard_depth:
            queue.popleft()

    def run(self) -> tuple[CallFrame, Action] | None:
        """Run until the queue is empty or the quota is spent (``cut``); returns the first entry
        the quota stopped, if any, so the caller can say where."""
        self._push_new()
        while True:
            if self.quota <= 0:
                # The game logs the cut even when nothing is left to run.
                self.cut = True
                return self._queue[0] if self._queue else None
            if not self._queue:
                return None
            frame, action = self._queue.popleft()
            try:
                action(self, frame)
            except Exception as exc:  # a bug here must not stop the rest of the pack
                self.on_internal_error(action, exc)
            if self.overflowed:
                return None
            self._push_new()

    def _push_new(self) -> None:
        self._queue.extendleft(reversed(self._new))
        self._new.clear()


def schedule_each(queue: ExecutionQueue, frame: CallFrame, items: list, make: Callable[[object], Action]) -> None:
    """``ContinuationTask.schedule``: one entry per item, queued lazily for 3 or more items so a
    long list does not sit in the queue all at once (the order of execution is the same)."""
    if len(items) <= 2:
        for item in items:
            queue.queue_next(frame, make(item))
        return
    index = 0
    upcoming = make(items[0])

    def step(q: ExecutionQueue, f: CallFrame) -> None:
        nonlocal index, upcoming
        q.queue_next(f, upcoming)
        index += 1
        if index < len(items):
            upcoming = make(items[index])
            step.entry = getattr(upcoming, "entry", None)
            q.queue_next(f, step)

    # where this entry would go next, for the quota-cut diagnostic
    step.entry = getattr(upcoming, "entry", None)
    queue.queue_next(frame, step)
