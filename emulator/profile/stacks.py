"""Call stacks for the profiler: the reference backend with a recorder of who called what.

:class:`StackBackend` is the reference (pure-Python) backend whose interpreter also records, for
every quota unit charged, the call stack it was charged in (root first), the number of calls per
function and, on request, the game's ``/debug function`` trace. The costs themselves are the
reference backend's (the same as the VM's, see :mod:`emulator.runtime.backend`): ``sum(stacks.values())``
equals the commands executed, because each root's own call (charged on no line) is counted as a
one-function stack.

The interpreter runs queued actions long after they were made, so the recorder remembers the
activation (function and caller chain) of the action running now; a charge whose source line is
not in that function (an action that left no activation behind) belongs to the nearest caller
whose file it is in.
"""
from __future__ import annotations

from collections import Counter

from emulator.profile.formats import TraceWriter
from emulator.reference import ReferenceBackend
from emulator.reference.engine import Interpreter
from emulator.reference.queue import chain


class StackInterpreter(Interpreter):
    def __init__(self, packs, state, sanitize: bool = False, trace: TraceWriter | None = None) -> None:
        super().__init__(packs, state, sanitize)
        self.stacks: Counter[tuple[str, ...]] = Counter()
        self.calls: Counter[str] = Counter()
        self.root_calls: Counter[str] = Counter()  # roots run (each charged 1 on no line)
        self.trace = trace
        self._current = None  # the Activation of the action running now
        self._paths = {fid: f.path for fid, f in packs.functions.items()}

    def run_root(self, function_id: str, context=None, arguments=None):
        if self.trace is not None:
            self.trace.root(function_id)
        self._current = None
        result = super().run_root(function_id, context, arguments)
        if result.cost:  # the root's own CallFunction, charged on no line
            self.stacks[(function_id,)] += 1
            self.calls[function_id] += 1
            self.root_calls[function_id] += 1
        return result

    # ------------------------------------------------------------------ where each charge goes
    def _count(self, loc) -> None:
        super()._count(loc)
        self.stacks[self._stack(loc.path)] += 1

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
            if call_loc is not None:
                self.calls[function.id] += 1
            if self.trace is not None:
                self.trace.call(frame.depth, function.id, size)
            action(queue, frame)

        call.entry = action.entry
        return call

    def _unbound(self, command, source):
        action = super()._unbound(command, source)
        if self.trace is None:
            return action

        def build(queue, frame) -> None:
            self.trace.command(frame.depth, self._text(command.loc))
            action(queue, frame)

        build.entry = action.entry
        return build

    def _execute_command(self, line, command, source):
        if self.trace is None:
            inner = super()._execute_command(line, command, source)
        else:
            depth = [0]
            text = self._text(line.loc)

            def traced(success: bool, value: int) -> None:
                if success:  # the game traces a result only when the command did not throw
                    self.trace.result(depth[0], text, value)

            inner = super()._execute_command(line, command, source.with_callback(chain(source.callback, traced)))

        def execute(queue, frame) -> None:
            self._current = source.activation
            if self.trace is not None:
                depth[0] = frame.depth
            inner(queue, frame)

        execute.entry = inner.entry
        return execute

    def _fail(self, failure, source, line) -> None:
        if self.trace is not None:
            self.trace.error(failure.message)
        super()._fail(failure, source, line)

    def _text(self, loc) -> str:
        lines = self.packs.sources.get(loc.path)
        if not lines or not 0 < loc.line <= len(lines):
            return "?"
        return lines[loc.line - 1][loc.col - 1:].strip()


class StackBackend(ReferenceBackend):
    """The reference backend, recording stacks (and a trace when given a :class:`TraceWriter`)."""

    name = "python"

    def __init__(self, trace: TraceWriter | None = None) -> None:
        super().__init__()
        self.trace = trace

    def load(self, packs, state, sanitize: bool = False) -> None:
        self._interpreter = StackInterpreter(packs, state, sanitize, self.trace)

    @property
    def stacks(self) -> Counter:
        return self._interpreter.stacks

    @property
    def calls(self) -> Counter:
        return self._interpreter.calls

    @property
    def root_calls(self) -> Counter:
        return self._interpreter.root_calls
