"""The reference backend: a plain-Python interpreter of the AST, the oracle the numba VM's control
flow is checked against. Clarity over speed; it follows the game's execution model task by task.
What each command does is not here: both backends run :mod:`emulator.commands`.

Modules
- :mod:`.queue`       the command queue of one root (ExecutionContext): frames, quota, cost
- :mod:`.engine`      function calls, execute chains, ``function``/``return``/``if function``,
                      and the call recording (calls, charges in their call stacks, the trace)
- :mod:`.source`      command sources (context, callback, activation) and call traces
- :mod:`.adapter`     the interpreter as the commands' environment; stages and stores on sources
"""
from __future__ import annotations

from emulator.runtime.backend import CallRecorder, RootResult, Tracer
from emulator.world.context import Context
from emulator.world.state import WorldState

from .engine import Interpreter


class ReferenceBackend:
    """Implements :class:`emulator.runtime.backend.Backend` and
    :class:`~emulator.runtime.backend.CallRecording`."""

    name = "python"

    def __init__(self) -> None:
        self._interpreter: Interpreter | None = None
        self._recorder: CallRecorder | None = None
        self._tracer: Tracer | None = None

    def record_calls(self, recorder: CallRecorder, tracer: Tracer | None = None) -> None:
        self._recorder, self._tracer = recorder, tracer

    def load(self, packs, state: WorldState, sanitize: bool = False) -> None:
        self._interpreter = Interpreter(packs, state, sanitize, self._recorder, self._tracer)
        self._packs, self._sanitize = packs, sanitize

    def new_world(self, state: WorldState) -> None:
        """Nothing is compiled: the interpreter starts again on ``state``."""
        self.load(self._packs, state, self._sanitize)

    def run_root(self, function_id: str, context: Context | None = None, arguments=None) -> RootResult:
        if self._interpreter is None:
            raise RuntimeError("ReferenceBackend.run_root called before load()")
        return self._interpreter.run_root(function_id, context, arguments)

    def line_counts(self) -> dict[tuple[str, int], int]:
        return dict(self._interpreter.line_counts) if self._interpreter else {}


__all__ = ["ReferenceBackend"]
