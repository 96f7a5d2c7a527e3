"""The interpreter: function calls, execute chains and custom commands on the command queue.

The structure follows the game's execution package (1.20.3+) task by task, so that results,
returns and command costs agree with it by construction:

- ``_call_function``      CallFunction      (costs 1, opens a frame one deeper)
- ``_build_contexts``     BuildContexts     (each redirect/fork stage costs 1 once)
- ``_execute_command``    ExecuteCommand    (the final command, 1 per source)
- ``_fallthrough``        FallthroughTask   (a ``return run``/``if function`` that got no return)
- ``_isolated_call``      IsolatedCall      (``execute if function``: a frame of its own)
- ``_run_function_command`` / ``_return``   the custom executors of ``function`` and ``return``

See :mod:`emulator.runtime.backend` for the cost rule both backends share. Given a
:class:`~emulator.runtime.backend.CallRecorder` and a :class:`~emulator.runtime.backend.Tracer`,
the interpreter tells them what happens where the game would: each call (charged on the caller's
line), each quota unit with the call stack it is charged in, and to the tracer each root, command,
result and error. Without them each of those points costs one ``is None`` test.
"""
from __future__ import annotations

from collections import Counter

from emulator.commands.advancements import earned_rewards
from emulator.commands.data import macro_arguments
from emulator.world.errors import CommandFailure
from emulator.commands.server import require_function
from emulator.runtime.backend import CallRecorder, RootResult, Tracer, report_quota_cut
from emulator.runtime.macros import MacroExpander
from emulator.world.semantics import wrap32
from emulator.world.context import Context
from emulator.world.state import WorldState
from mcfunction_parser import ast

from . import adapter
from .queue import Action, CallFrame, ExecutionQueue, chain, schedule_each
from .source import Activation, Source

_CUSTOM_FINAL = (ast.FunctionCall, ast.Return)

# Stages built with ``fork`` in ExecuteCommand.register (errors in one context don't stop others)
FORKS = (ast.ExAs, ast.ExAt, ast.ExPositionedAs, ast.ExRotatedAs, ast.ExFacingEntity, ast.ExOn, ast.Condition)


class Interpreter:
    def __init__(self, packs, state: WorldState, sanitize: bool = False, recorder: CallRecorder | None = None,
                 tracer: Tracer | None = None) -> None:
        self.packs = packs
        self.state = state
        self.macros = MacroExpander(packs.version)
        self.env = adapter.ReferenceEnv(state, packs, sanitize)
        self.line_counts: Counter[tuple[str, int]] = Counter()
        self._stages: dict[int, tuple[ast.Command, tuple]] = {}
        self.recorder = recorder
        self.tracer = tracer

    # ------------------------------------------------------------------ roots
    def run_root(self, function_id: str, context: Context | None = None, arguments=None) -> RootResult:
        """``ExecutionContext.queueInitialFunctionCall`` then ``runCommandQueue``."""
        if self.tracer is not None:
            self.tracer.root(function_id)
        function = self.packs.functions.get(function_id)
        if function is None:
            self.state.error(f"Unknown function {function_id}")
            return RootResult(0, None)
        try:
            commands = self.macros.instantiate(function, arguments)
        except CommandFailure as failure:
            self.state.error(failure.message)
            return RootResult(0, None)
        result: list[int | None] = [None]
        succeeded: list[bool | None] = [None]

        def on_result(success: bool, value: int) -> None:
            result[0], succeeded[0] = (value if success else 0), success

        limit = self.state.gamerules.max_command_chain_length
        queue = ExecutionQueue(limit, self.state.gamerules.max_command_fork_count, self._internal_error)
        source = Source(context or Context(pos=self.state.level_settings.server_position()), None, None)
        top = CallFrame(0, None, 0)
        queue.queue_next(top, self._call_function(function, commands, source, on_result, False, None))
        stopped = queue.run()
        if queue.overflowed:
            self.state.error("Command execution stopped due to command queue overflow (max 10000000)")
        if queue.cut:
            report_quota_cut(self.state, limit, _where(stopped))
        return RootResult(queue.cost, result[0], queue.cut, succeeded[0])

    # ------------------------------------------------------------------ tasks
    def _call_function(self, function: ast.Function, commands, source: Source, result_callback,
                       return_parent: bool, call_loc) -> Action:
        def call(queue: ExecutionQueue, frame: CallFrame) -> None:
            self._charge_call(queue, function.id, source.activation, call_loc)
            if self.tracer is not None:
                self.tracer.call(frame.depth, function.id, len(commands))
            depth = frame.depth + 1
            new_frame = CallFrame(depth, result_callback, frame.discard_depth if return_parent else depth)
            bound = source.in_function(Activation(function.id, source.activation, call_loc))
            schedule_each(queue, new_frame, list(commands), lambda command: self._unbound(command, bound))

        call.entry = (function.id, source.activation, call_loc)
        return call

    def _unbound(self, command: ast.Command, source: Source):
        def build(queue: ExecutionQueue, frame: CallFrame) -> None:
            if self.tracer is not None:
                self.tracer.command(frame.depth, self._command_text(command.loc))
            self._build_contexts(queue, frame, command, 0, [source], False, False, source.activation)

        build.entry = (source.activation.function, source.activation, command.loc)
        return build

    def _build_contexts(self, queue, frame, line: ast.Command, index: int, sources: list[Source],
                        forked: bool, is_return: bool, activation: Activation) -> None:
        """The chain of ``line`` (run in ``activation``) from stage ``index`` on, for ``sources``."""
        stages = self._stages_of(line)
        while index < len(stages) - 1:
            stage = stages[index]
            forked = forked or isinstance(stage, FORKS)
            if isinstance(stage, ast.IfFunction):
                self._if_function(queue, frame, line, index, sources, forked, is_return, activation)
                return
            if isinstance(stage, ast.Return):
                self._return_run(queue, frame, line, index, sources, forked, activation)
                return
            self._charge(queue, line.loc, activation)
            produced: list[Source] = []
            fork_limit = queue.fork_limit
            for source in sources:
                try:
                    out = adapter.apply(self.env, stage, source, line.loc)
                except CommandFailure as failure:
                    self._fail(failure, source, line)
                    if not forked:
                        return
                    continue
                if len(produced) + len(out) >= fork_limit:
                    # BuildContexts.ERROR_FORK_LIMIT_REACHED: a stage would produce the limit or more
                    self._fail(CommandFailure("command.forkLimit", fork_limit, report=True), source, line)
                    return
                produced.extend(out)
            sources = produced
            index += 1
        final = stages[-1]
        if not sources:
            if is_return:
                queue.queue_next(frame, _fallthrough)
            return
        if isinstance(final, _CUSTOM_FINAL):
            for source in sources:
                self._custom(queue, frame, line, final, source, is_return)
            return
        if is_return:
            first = sources[0]
            sources = [first.with_callback(chain(first.callback, frame.on_return))]
        schedule_each(queue, frame, sources, lambda source: self._execute_command(line, final, source))

    def _execute_command(self, line: ast.Command, command, source: Source):
        def execute(queue: ExecutionQueue, frame: CallFrame) -> None:
            self._charge(queue, line.loc, source.activation)
            try:
                value = adapter.run_command(self.env, command, source, line.loc)
            except CommandFailure as failure:
                self._fail(failure, source, line)
                if source.callback is not None:
                    source.callback(False, 0)
            else:
                if source.callback is not None:
                    source.callback(True, value)
                if self.tracer is not None:  # the game traces a result only when the command did not throw
                    self.tracer.result(frame.depth, self._command_text(line.loc), value)
            if self.state.pending_rewards:
                self._queue_rewards(queue, frame, source.activation)

        execute.entry = (source.activation.function, source.activation, line.loc)
        return execute

    def _queue_rewards(self, queue: ExecutionQueue, frame: CallFrame, caller: Activation) -> None:
        """AdvancementRewards.grant inside a command: ServerFunctionManager.execute queues each reward
        function earned (ExecutionContext.queueInitialFunctionCall) to run right after the command,
        in a top frame one deeper than the command's (createTopFrame), as the player, its result
        going nowhere (CommandResultCallback.EMPTY). Its call is charged on no line, in the
        caller's stack."""
        top = CallFrame(frame.depth + 1, None, frame.depth + 1)
        for function_id, context in earned_rewards(self.state, self.packs.functions):
            function = self.packs.functions[function_id]
            try:
                commands = self.macros.instantiate(function, None)
            except CommandFailure as failure:  # the game drops a macro reward (FunctionInstantiationException)
                self.state.error(failure.message, caller.frames(None))
                continue
            queue.queue_next(top, self._call_function(function, commands, Source(context, None, caller), None,
                                                      False, None))

    # ------------------------------------------------------------------ custom stages
    def _return_run(self, queue, frame, line, index, sources, forked, activation) -> None:
        """ReturnFromCommandCustomModifier: discard the rest of the function, run the rest of the
        chain as a new entry whose result is the function's return."""
        if not sources:
            return
        queue.discard(frame)

        def rest(q: ExecutionQueue, f: CallFrame) -> None:
            self._build_contexts(q, f, line, index + 1, sources, forked, True, activation)

        rest.entry = (sources[0].activation.function, sources[0].activation, line.loc)
        queue.queue_next(frame, rest)

    def _if_function(self, queue, frame, line, index, sources, forked, is_return, activation) -> None:
        """ExecuteCommand.scheduleFunctionConditionsAndTest: each source calls the functions in a
        frame of its own; the sources whose result passes the check go on to the rest of the chain.
        A function that never returns reaches FallthroughTask: result 0, so ``if`` fails and
        ``unless`` passes."""
        stage: ast.IfFunction = self._stages_of(line)[index]
        origin = sources[0] if sources else None
        try:
            functions = self._functions(stage.function, stage.is_tag)
        except CommandFailure as failure:
            self._fail(failure, origin, line)
            return
        if not functions:
            return
        instances = []
        for function in functions:
            try:
                instances.append((function, self.macros.instantiate(function, None)))
            except CommandFailure as failure:
                self._fail(failure, origin, line)
        passed: list[Source] = []
        for source in sources:
            queue.queue_next(frame, self._isolated_call(instances, source, stage.negated, passed, line.loc))

        def rest(q: ExecutionQueue, f: CallFrame) -> None:
            self._build_contexts(q, f, line, index + 1, passed, forked, is_return, activation)

        rest.entry = (origin.activation.function, origin.activation, line.loc) if origin else None
        queue.queue_next(frame, rest)

    def _isolated_call(self, instances, source: Source, negated: bool, passed: list, call_loc):
        def output(success: bool, value: int) -> None:
            if (value == 0) if negated else (value != 0):
                passed.append(source)

        sender = source.with_callback(None)

        def isolated(queue: ExecutionQueue, frame: CallFrame) -> None:
            depth = frame.depth + 1
            inner = CallFrame(depth, output, depth)
            for function, commands in instances:
                queue.queue_next(inner, self._call_function(function, commands, sender, inner.on_return, True, call_loc))
            queue.queue_next(inner, _fallthrough)

        return isolated

    # ------------------------------------------------------------------ custom final commands
    def _custom(self, queue, frame, line, command, source: Source, is_return: bool) -> None:
        if isinstance(command, ast.Return):
            self._return(queue, frame, command, source)
            return
        try:
            self._run_function_command(queue, frame, line, command, source, is_return)
        except CommandFailure as failure:
            # CustomCommandExecutor.WithErrorHandling: source.callback().onFailure(); after `return
            # run` that callback carries the frame's return (BuildContexts), so the function fails
            self._fail(failure, source, line)
            callback = chain(source.callback, frame.on_return) if is_return else source.callback
            if callback is not None:
                callback(False, 0)

    def _return(self, queue, frame, command: ast.Return, source: Source) -> None:
        """ReturnValueCustomExecutor / ReturnFailCustomExecutor."""
        if command.kind == "fail":
            if source.callback is not None:
                source.callback(False, 0)
            frame.return_failure()
        else:
            if source.callback is not None:
                source.callback(True, command.value)
            frame.return_success(command.value)
        queue.discard(frame)

    def _run_function_command(self, queue, frame, line, command: ast.FunctionCall, source, is_return) -> None:
        """FunctionCommand: queue a CallFunction per function (instantiated with the arguments)."""
        functions = self._functions(command.function, command.is_tag)
        if not functions:
            # FunctionCommand.ERROR_NO_FUNCTIONS; reported, as an empty tag is a pack mistake
            raise CommandFailure("commands.function.scheduled.no_functions", f"#{command.function}", report=True)
        arguments = self._call_arguments(command, source)
        sender = source.with_callback(None)
        if is_return:
            callback = chain(source.callback, frame.on_return)
            for function in functions:
                commands = self.macros.instantiate(function, arguments)
                queue.queue_next(frame, self._call_function(function, commands, sender, callback, True, line.loc))
            queue.queue_next(frame, _fallthrough)
            return
        callback = source.callback
        if len(functions) > 1 and callback is not None:
            callback, report = _accumulator(callback)
        else:
            report = None
        for function in functions:
            commands = self.macros.instantiate(function, arguments)
            queue.queue_next(frame, self._call_function(function, commands, sender, callback, False, line.loc))
        if report is not None:
            queue.queue_next(frame, report)

    def _call_arguments(self, command: ast.FunctionCall, source: Source):
        if command.with_source is None:
            return command.arguments
        return macro_arguments(self.env.at(source, command.loc), command.with_source, command.with_path, source.context)

    def _functions(self, name: str, is_tag: bool) -> list[ast.Function]:
        require_function(self.env, name, is_tag)
        if not is_tag:
            return [self.packs.functions[name]]
        return [self.packs.functions[f] for f in self.packs.resolve_tag(name) if f in self.packs.functions]

    # ------------------------------------------------------------------ helpers
    def _internal_error(self, action, exc: Exception) -> None:
        self.state.error(f"internal error in the reference backend: {type(exc).__name__}: {exc}", _where((None, action)))

    def _fail(self, failure: CommandFailure, source: Source | None, line: ast.Command) -> None:
        if self.tracer is not None:
            self.tracer.error(failure.message)
        if failure.report:
            frames = source.activation.frames(line.loc) if source and source.activation else ()
            self.state.error(failure.message, frames, unmodelled=failure.unmodelled)

    def _charge_call(self, queue: ExecutionQueue, function_id: str, caller: Activation | None, call_loc) -> None:
        """CallFunction's unit: on the caller's line, or, for a root's own call and a reward's, on no
        line and in the stack of the function called (under its caller's, for a reward)."""
        if call_loc is None:
            queue.charge()
            if self.recorder is not None:
                self.recorder.charge((caller.stack() if caller is not None else ()) + (function_id,))
            return
        if self.recorder is not None:
            self.recorder.call(function_id)
        self._charge(queue, call_loc, caller)

    def _charge(self, queue: ExecutionQueue, loc, activation: Activation) -> None:
        """One quota unit, on ``loc``'s line, in ``activation``'s call stack."""
        queue.charge()
        self.line_counts[loc[:2]] += 1  # (path, line)
        if self.recorder is not None:
            self.recorder.charge(activation.stack())

    def _command_text(self, loc) -> str:
        """The command at ``loc`` as the trace shows it: its source line from its column on."""
        lines = self.packs.sources.get(loc.path)
        if not lines or not 0 < loc.line <= len(lines):
            return "?"
        return lines[loc.line - 1][loc.col - 1:].strip()

    def _stages_of(self, command: ast.Command) -> tuple:
        cached = self._stages.get(id(command))
        if cached is None or cached[0] is not command:
            cached = (command, stages(command))
            self._stages[id(command)] = cached
        return cached[1]


def stages(command: ast.Command) -> tuple:
    """A command as the game's ContextChain: execute subcommands (``run`` dropped: it has no
    modifier), ``return run`` as a stage, then the final command. An execute that ends with a
    condition has that condition as its final command."""
    out: list = []
    while True:
        if isinstance(command, ast.Execute):
            if command.run is None:
                out.extend(command.subcommands[:-1])
                out.append(command.subcommands[-1])
                return tuple(out)
            out.extend(command.subcommands)
            command = command.run
        elif isinstance(command, ast.Return) and command.kind == "run":
            out.append(command)
            command = command.command
        else:
            out.append(command)
            return tuple(out)


def _fallthrough(queue: ExecutionQueue, frame: CallFrame) -> None:
    """FallthroughTask: the called functions did not return: the frame returns failure."""
    frame.return_failure()
    queue.discard(frame)


def _accumulator(callback):
    """FunctionCommand's Accumulator for a tag called with a callback: the sum of the members'
    returns (Java int), reported once after them if any returned."""
    state = {"any": False, "sum": 0}

    def add(success: bool, value: int) -> None:
        state["any"] = True
        state["sum"] = wrap32(state["sum"] + value)

    def report(queue: ExecutionQueue, frame: CallFrame) -> None:
        if state["any"]:
            callback(True, state["sum"])

    return add, report


def _where(stopped):
    """Frames for the entry the quota stopped (from the ``entry`` tag the tasks carry)."""
    if stopped is None:
        return ()
    action = stopped[1]
    entry = getattr(action, "entry", None)
    if entry is None:
        return ()
    function, activation, loc = entry
    if activation is None:
        return ()
    return activation.frames(loc)
