"""The reference backend's call recording (:class:`emulator.runtime.backend.CallRecording`).

:class:`RecordingReferenceBackend` is the reference backend; after ``record_calls(recorder,
tracer)`` its interpreter also reports every function call, every quota unit with the call stack
it was charged in, and (to the tracer) each command and its result. The costs are the reference
backend's own: the recorder hears exactly the charges the run made.

The interpreter runs queued actions long after they were made, so the recording remembers the
activation (function and caller chain) of the action running now; a charge whose source line is
not in that function (an action that left no activation behind) belongs to the nearest caller
whose file it is in.
"""
from __future__ import annotations

from emulator.runtime.backend import CallRecorder, Tracer
from emulator.world.state import WorldState

from . import ReferenceBackend
from .engine import Interpreter
from .queue import chain


class RecordingInterpreter(Interpreter):
    def __init__(self, packs, state: WorldState, sanitize: bool, recorder: CallRecorder,
                 tracer: Tracer | None) -> None:
        super().__init__(packs, state, sanitize)
        self.recorder = recorder
        self.tracer = tracer
        self._current = None  # the Activation of the action running now
        self._paths = {fid: f.path for fid, f in packs.functions.items()}

    def run_root(self, function_id: str, context=None, arguments=None):
        if self.tracer is not None:
            self.tracer.root(function_id)
        self._current = None
        return super().run_root(function_id, context, arguments)

    # ------------------------------------------------------------------ where each charge goes
    def _count(self, loc) -> None:
        super()._count(loc)
        self.recorder.charge(self._stack(loc.path))

    def _stack(self, path: str) -> tuple[str, ...]:
        here = self._current
        while here is not None and self._paths.get(here.function) != path:
            here = here.parent
        out: list[str] = []
        while here is not None:
            out.append(here.function)
            here = here.parent
        return tuple(reversed(out)) or (path,)

    def _build_contexts(self, queue, frame, line, index, sources, forked, is_return) -> None:
        if sources:
            self._current = sources[0].activation
        super()._build_contexts(queue, frame, line, index, sources, forked, is_return)

    def _call_function(self, function, commands, source, result_callback, return_parent, call_loc):
        action = super()._call_function(function, commands, source, result_callback, return_parent, call_loc)
        size = len(commands)

        def call(queue, frame) -> None:
            self._current = source.activation  # the call is charged on the caller's line
            if call_loc is None:  # a root's own CallFunction, charged on no line
                self.recorder.charge((function.id,))
            else:
                self.recorder.call(function.id)
            if self.tracer is not None:
                self.tracer.call(frame.depth, function.id, size)
            action(queue, frame)

        call.entry = action.entry
        return call

    # ------------------------------------------------------------------ the trace
    def _unbound(self, command, source):
        action = super()._unbound(command, source)
        if self.tracer is None:
            return action

        def build(queue, frame) -> None:
            self.tracer.command(frame.depth, self._text(command.loc))
            action(queue, frame)

        build.entry = action.entry
        return build

    def _execute_command(self, line, command, source):
        if self.tracer is None:
            inner = super()._execute_command(line, command, source)
        else:
            depth = [0]
            text = self._text(line.loc)

            def traced(success: bool, value: int) -> None:
                if success:  # the game traces a result only when the command did not throw
                    self.tracer.result(depth[0], text, value)

            inner = super()._execute_command(line, command, source.with_callback(chain(source.callback, traced)))

        def execute(queue, frame) -> None:
            self._current = source.activation
            if self.tracer is not None:
                depth[0] = frame.depth
            inner(queue, frame)

        execute.entry = inner.entry
        return execute

    def _fail(self, failure, source, line) -> None:
        if self.tracer is not None:
            self.tracer.error(failure.message)
        super()._fail(failure, source, line)

    def _text(self, loc) -> str:
        lines = self.packs.sources.get(loc.path)
        if not lines or not 0 < loc.line <= len(lines):
            return "?"
        return lines[loc.line - 1][loc.col - 1:].strip()


class RecordingReferenceBackend(ReferenceBackend):
    """The reference backend, recording calls once :meth:`record_calls` named a recorder."""

    def __init__(self) -> None:
        super().__init__()
        self._recording: tuple[CallRecorder, Tracer | None] | None = None

    def record_calls(self, recorder: CallRecorder, tracer: Tracer | None = None) -> None:
        self._recording = (recorder, tracer)

    def load(self, packs, state: WorldState, sanitize: bool = False) -> None:
        if self._recording is None:
            super().load(packs, state, sanitize)
        else:
            self._interpreter = RecordingInterpreter(packs, state, sanitize, *self._recording)
