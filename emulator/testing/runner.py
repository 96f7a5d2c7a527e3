"""Running test cases: each in a fresh world (its pack loaded, ``#minecraft:load`` run), steps in
order, ``await`` ticking the world (``#minecraft:tick``, schedules) until the test's timeout."""
from __future__ import annotations

import os
import random
import re
import time
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path

from emulator.commands import entities as world_entities
from emulator.api import Emulator
from emulator.commands import stages
from emulator.commands.env import Env
from emulator.world.errors import CommandFailure
from emulator.world.context import Context
from emulator.testing import chat, environments
from emulator.testing.discovery import TestFile, selected
from emulator.testing.dummies import Dummies, DummyFailure, Unsupported
from emulator.testing.results import FAILED, INCONCLUSIVE, PASSED, Summary, TestResult
from emulator.testing.testfile import (
    ChatCheck, Check, Delay, Dummy, Fail, InsideCheck, PerContext, Run, Succeed, TestCase, read_test,
)
from emulator.world import structures
from emulator.world.blocks import BlockSpec
from emulator.world.entities import Entity
from mcfunction_parser.diagnostics import Diagnostic
from mcfunction_parser.nbt import Compound, to_snbt
from mcfunction_parser.pack.loader import load_packs

_SCORE_MATCHES = re.compile(r"score (\S+) (\S+) matches (\S+)$")
_SCORE_COMPARE = re.compile(r"score (\S+) (\S+) (<=|>=|=|<|>) (\S+) (\S+)$")
_ENTITY = re.compile(r"entity (.+)$")
_CONTEXT_BOUND = re.compile(r"@s|[~^]")  # a condition whose meaning depends on the context
_DATA = re.compile(r"data (?:storage (\S+) |entity (?:\S+\[.*\]|\S+) |block \S+ \S+ \S+ )(.+)$")


class _Verdict(Exception):
    def __init__(self, status: str, message: str = "", line: int | None = None) -> None:
        super().__init__(message)
        self.status, self.message, self.line = status, message, line


def shown_path(path) -> str:
    """A path as messages show it: relative to the working folder when inside it (``path`` may lie
    inside a .zip pack: a zipfile.Path)."""
    text = str(path)
    rel = os.path.relpath(text)
    return Path(text).as_posix() if rel.startswith("..") else Path(rel).as_posix()


def load_suite(files: list[TestFile], pattern: str | None = None, with_packs=(), together: bool = False, game_jar=None):
    """Parse each pack once and its test files; yield ``(packs, [TestCase])`` per pack with the
    generated functions added to ``packs.functions``.

    ``with_packs`` (libraries, the other modules a pack needs) load first, beneath each pack under
    test, as a CI server loads them. ``together``: every pack under test loads into one world with
    them (in the order given, as a collection's CI runs all its modules' tests on one server), and
    every test runs there. ``game_jar``: the game's jar (vanilla tags)."""
    by_pack: dict[Path, list[TestFile]] = {}
    for tf in selected(files, pattern):
        by_pack.setdefault(tf.pack_root, []).append(tf)
    extra = [Path(p).resolve() for p in with_packs]
    if together and by_pack:
        roots = [r for r in by_pack if r not in extra]
        by_pack = {tuple(roots): [tf for group in by_pack.values() for tf in group]}
    key = 0
    for root, pack_files in by_pack.items():
        under_test = list(root) if isinstance(root, tuple) else [root]
        packs = load_packs([*extra, *(r for r in under_test if r not in extra)], game_jar=game_jar)
        cases = []
        for tf in pack_files:
            cases.append(read_test(tf.id, tf.path, shown_path(tf.path), f"t{key}", packs.version))
            key += 1
        for case in cases:
            packs.functions.update(case.functions)
        yield packs, _in_batches(cases)


def _in_batches(cases: list[TestCase]) -> list[TestCase]:
    """Order by batch (first appearance) and give every test of a batch the batch's
    @beforebatch/@afterbatch; a second, different one in a batch is an error of the test giving
    it (PackTest allows one per batch). As each test has a world of its own, the batch's commands
    run in each test's world, before and after the test."""
    batches: dict[str, list[TestCase]] = {}
    hooks: dict[tuple[str, str], tuple[str, str | None]] = {}  # (batch, directive) -> (text, function)
    for case in cases:
        d = case.directives
        for name, given, function in (("@beforebatch", d.before_batch, case.before_batch),
                                      ("@afterbatch", d.after_batch, case.after_batch)):
            if given is None:
                continue
            first = hooks.setdefault((d.batch, name), (given[0], function))[0]
            if first != given[0]:
                message = f"{name}: batch {d.batch!r} already has {first!r}"
                case.errors.append(Diagnostic.at("error", message, given[1]))
        batches.setdefault(d.batch, []).append(case)
    for batch, members in batches.items():
        for case in members:
            case.before_batch = hooks.get((batch, "@beforebatch"), (None, None))[1]
            case.after_batch = hooks.get((batch, "@afterbatch"), (None, None))[1]
    return [case for members in batches.values() for case in members]


def run_suite(files: list[TestFile], backend: str = "numba", pattern: str | None = None,
              on_result: Callable[[TestResult], None] | None = None, on_load=None, strict: bool = False,
              with_packs=(), together: bool = False, allow_unmodelled: bool = False, game_jar=None) -> Summary:
    """Run every test in ``files`` (those whose id contains ``pattern``, case-insensitively);
    ``strict``: a runtime error during a test fails it; ``with_packs`` and ``together`` as
    :func:`load_suite`; ``allow_unmodelled``: a test that met something the emulator does not
    model passes or fails as it ran (else it is inconclusive)."""
    summary = Summary()
    for packs, cases in load_suite(files, pattern, with_packs, together, game_jar):
        if on_load is not None:
            on_load(packs)
        for case in cases:
            result = run_case(case, packs, backend, strict, allow_unmodelled)
            summary.results.append(result)
            if on_result is not None:
                on_result(result)
    return summary


def fresh_world(packs, backend: str) -> Emulator:
    """An emulator on already parsed ``packs`` with an empty world, started with :func:`run_load`."""
    emu = Emulator(backend=backend)
    emu.load_parsed(packs)
    return run_load(emu)


def run_load(emu: Emulator) -> Emulator:
    """Run ``#minecraft:load`` now (:meth:`Emulator.start`): a test starts in a running world."""
    emu.start()
    return emu


def run_case(case: TestCase, packs, backend: str = "numba", strict: bool = False,
             allow_unmodelled: bool = False) -> TestResult:
    result = TestResult(case.id, case.path, PASSED, optional=case.directives.optional)
    if case.errors:
        first = case.errors[0]
        result.status, result.message, result.line = FAILED, first.message, first.line
        result.details = [d.format() for d in case.errors]
        return result
    started = time.perf_counter()
    emu = fresh_world(packs, backend)
    emu.tick()  # the rest of the server's first tick: GameTestServer.startTests runs after it
    source = TestSource(emu, Dummies(emu.state))
    try:
        prepare(source, packs, case)
        source.dummy_entity = spawn_dummy(source, case)
        _run_steps(emu, source, case)
    except _Verdict as verdict:
        result.status, result.message, result.line = verdict.status, verdict.message, verdict.line
    except Exception as error:  # an emulator bug fails this test, not the suite
        result.status, result.message = FAILED, f"internal error: {type(error).__name__}: {error}"
    for function in source.environment.teardown if source.environment else ():
        emu.call(function)
    if case.after_batch:
        emu.call(case.after_batch)
    result.ticks = emu.ticks - source.started
    result.seconds = time.perf_counter() - started
    errors = [d for d in emu.diagnostics if d.severity == "error"]
    unmodelled = [d for d in emu.diagnostics if d.unmodelled]
    if result.status in (PASSED, FAILED) and unmodelled and not allow_unmodelled:
        # what the test saw may hang on the missing behaviour: neither a pass nor a failure
        first = unmodelled[0]
        where = f"{first.frames[-1].loc}: " if first.frames else ""
        verdict = f"the test {'passed' if result.status == PASSED else 'failed (' + result.message + ')'}"
        result.status, result.message = INCONCLUSIVE, f"{where}{first.message}; {verdict}"
        result.line = first.frames[-1].loc.line if first.frames else result.line
    elif result.status == PASSED and errors and strict:
        result.status, result.message = FAILED, f"{len(errors)} runtime error(s) during the test (--strict)"
    # shown with the test: every diagnostic when it did not pass, the runtime errors when it did
    shown = emu.diagnostics if result.status != PASSED else errors
    result.details = list(dict.fromkeys(d.format() for d in shown))
    return result


_TEST_INSTANCES = (1, 21, 5)  # the game's own test instances and environments (PackTest 2)
_CHUNK_WAIT = 20  # GameTestInfo.ticksToWaitForChunkLoading before 1.21.5


def prepare(source: TestSource, packs, case: TestCase) -> None:
    """What the game does between the batch's start (the end of the server's first tick, after
    ``#minecraft:load``: GameTestServer.tickServer -> startTests) and the test's first line, then
    ``source.started``. From 1.21.5 (GameTestRunner.runBatch, GameTestInfo.startExecution and
    tickInternal): the structure is placed and encased, the environment set up, and the test
    starts in the game test ticker's second tick, after that tick's functions and block ticks
    (MinecraftServer.tickChildren ticks it last). Before (PackTest 1.x ticks the ticker first in
    each server tick, MinecraftServerMixin): the test is encased and the batch's function runs,
    the test waits 20 ticks (GameTestInfo.ensureStructureIsPlaced), then its structure is placed
    and it starts at the start of the next tick. A server slower to load the test's chunks waits
    longer; the emulator takes the shortest wait."""
    emu, version = source.emu, packs.version
    template = read_template(packs, case.directives.template) if case.directives.template else None
    source.size = template.size if template is not None else (1, 1, 1)
    if version >= _TEST_INSTANCES and template is not None:
        structures.place(emu.state, template, TestSource.block_origin())
    encase(emu, version, source.size, case.directives.sky_access)
    if case.before_batch:
        emu.call(case.before_batch)
    source.environment = set_up_environment(emu, packs, case.directives.environment)
    emu.tick(2 if version >= _TEST_INSTANCES else _CHUNK_WAIT)
    if version < _TEST_INSTANCES and template is not None:
        structures.place(emu.state, template, TestSource.block_origin())
    source.started = emu.ticks


def set_up_environment(emu: Emulator, packs, environment_id: str):
    """The test environment's rules and day time, then its setup functions (as the server, as
    TestEnvironmentDefinition.Functions runs them). One that cannot be set up fails the test; one
    the emulator does not model makes it inconclusive."""
    try:
        environment = environments.resolve(packs, environment_id)
    except environments.EnvironmentError as error:
        raise _Verdict(INCONCLUSIVE if error.unmodelled else FAILED, error.message) from None
    for rule, value in environment.rules:
        emu.state.gamerules.set(rule, value)
    if environment.day_time is not None:
        emu.state.daytime = environment.day_time
    for function in environment.setup:
        if function not in packs.functions:
            raise _Verdict(FAILED, f"test environment {environment_id}: unknown setup function {function}")
        emu.call(function)
    return environment


_BARRIER = BlockSpec("minecraft:barrier", False, (), None)
_FLOORED_ENCASING = (1, 21, 5)  # TestInstanceBlockEntity (1.21.5+) adds a floor; StructureUtils before it


def encase(emu: Emulator, version, size, sky_access: bool) -> None:
    """Barriers round the test structure, as the game encases a test: walls one block outside it, a
    ceiling unless the test has sky access, and from 1.21.5 a floor (TestInstanceBlockEntity.
    processStructureBoundary; StructureUtils.encaseStructure before)."""
    x0, y0, z0 = (int(c) for c in TestSource.ORIGIN)
    low = (x0 - 1, y0 - 1 if version >= _FLOORED_ENCASING else y0, z0 - 1)
    high = (x0 + size[0], y0 + size[1], z0 + size[2])
    floor = version >= _FLOORED_ENCASING
    for x in range(low[0], high[0] + 1):
        for y in range(low[1], high[1] + 1):
            for z in range(low[2], high[2] + 1):
                wall = x in (low[0], high[0]) or z in (low[2], high[2]) or (floor and y == low[1])
                if wall or (y == high[1] and not sky_access):
                    emu.state.blocks.setblock((x, y, z), _BARRIER)


def read_template(packs, template_id: str):
    """The test's structure (placed with its corner at the test source's block)."""
    data = structures.find_template(packs, template_id)
    if data is None:
        missing = structures.template_file(packs, template_id)
        raise _Verdict(FAILED, f"Missing test structure: {template_id} (no {missing})")
    try:
        return structures.read_template(data)
    except structures.StructureError as error:
        raise _Verdict(FAILED, f"Test structure {template_id}: {error}") from None


class TestSource:
    """Where test commands run (PackTestExecutor.createCommandSourceStack): as the server, or as the
    test's dummy, at the test structure's corner (0, 1, 0). PackTest 1.x ran them at the test's
    structure block + (0, 1, 0), which is where the structure block places a structure, and
    PackTest 2 at the test origin, the same corner. The dummy stays the source's entity even after
    it left or respawned, as in PackTest."""

    ORIGIN = (0.0, 1.0, 0.0)

    def __init__(self, emu: Emulator, dummies: Dummies, size=(1, 1, 1)) -> None:
        self.emu, self.dummies = emu, dummies
        self.size = size  # of the test structure, whose corner is ORIGIN
        self.dummy_entity: Entity | None = None
        self.environment = None  # the test environment set up for it
        self.started = emu.ticks  # the world's tick when its first line ran

    @classmethod
    def block_origin(cls) -> tuple[int, int, int]:
        return tuple(int(c) for c in cls.ORIGIN)

    def inside(self, entity: Entity) -> bool:
        """GameTestHelper.getBounds().inflate(1).contains(position): half-open on the far side."""
        return all(o - 1 <= p < o + s + 1 for p, o, s in zip(entity.pos, self.ORIGIN, self.size))

    @property
    def dummy(self) -> str | None:
        """The @dummy's UUID (None without one)."""
        return self.dummy_entity.uuid_string if self.dummy_entity is not None else None

    def context(self) -> Context:
        if self.dummy_entity is None:
            return Context(pos=self.ORIGIN)
        return replace(world_entities.entity_context(self.emu.state, self.dummy_entity), pos=self.ORIGIN)

    def call(self, function: str, context: Context | None = None) -> int | None:
        return self.emu.runtime.call(function, context or self.context()).result

    def contexts(self, step: PerContext) -> list[Context]:
        """The contexts an execute prefix makes from the test source, each stage over all
        contexts before the next (ContextChain.executeAll): a condition through its generated
        function, the other stages through emulator.commands; a stage that fails drops its context. One
        the emulator cannot evaluate here fails the test saying so."""
        emu = self.emu
        env = Env(emu.state, emu.packs.functions, emu.packs.tags)
        contexts = [self.context()]
        for stage, condition in zip(step.stages, step.conditions):
            if condition is not None:
                contexts = [ctx for ctx in contexts if self.call(condition, ctx) == 1]
                continue
            made = []
            for ctx in contexts:
                try:
                    made += stages.stage(env, stage, ctx)
                except CommandFailure as failure:
                    if failure.report:
                        raise _Verdict(FAILED, f"{failure.message} (in the execute prefix of a test command)",
                                       stage.loc.line) from None
            contexts = made
        return contexts


def spawn_dummy(source: TestSource, case: TestCase) -> Entity | None:
    """The @dummy player (PackTest's Dummy.createRandom: named Dummy100..Dummy999, here seeded by the
    test id), at the directive's position relative to the test origin."""
    if case.directives.dummy is None:
        return None
    pos = _position(case.directives.dummy, TestSource.ORIGIN)
    if pos is None:
        raise _Verdict(FAILED, "Failed to initialize test with dummy", 1)
    name = f"Dummy{random.Random(case.id).randrange(100, 1000)}"
    return source.dummies.spawn(name, pos)


def _position(text: str, origin: tuple[float, float, float]) -> tuple[float, float, float] | None:
    """An absolute or ``~``-relative position (Vec3Argument without ``^``), None if malformed."""
    parts = text.split()
    if len(parts) != 3:
        return None
    out = []
    for part, base in zip(parts, origin):
        relative = part.startswith("~")
        number = part[1:] if relative else part
        try:
            value = float(number) if number else (0.0 if relative else None)
        except ValueError:
            return None
        if value is None:
            return None
        out.append(base + value if relative else value)
    return tuple(out)


def _run_steps(emu: Emulator, source: TestSource, case: TestCase) -> None:
    timeout = case.directives.timeout
    chat_start = len(emu.log)  # chat conditions see the messages since the test started
    for step in case.steps:
        if step.gate and source.call(step.gate) != 1:
            continue
        if isinstance(step, Run):
            source.call(step.function)
        elif isinstance(step, (Check, ChatCheck, InsideCheck)) and step.mode == "assert":
            if not _holds(source, step, chat_start):
                raise _Verdict(FAILED, describe_failure(source, step, chat_start), step.loc.line)
        elif isinstance(step, (Check, ChatCheck, InsideCheck)):
            while not _holds(source, step, chat_start):
                _tick_or_time_out(source, timeout, step, describe_failure(source, step, chat_start))
        elif isinstance(step, Delay):
            for _ in range(step.ticks):
                _tick_or_time_out(source, timeout, step, f"still in 'await delay {step.ticks}'")
        elif isinstance(step, Fail):
            raise _Verdict(FAILED, step.message, step.loc.line)
        elif isinstance(step, Succeed):
            raise _Verdict(PASSED)
        elif isinstance(step, Dummy):
            _act(source, step, source.context())
        elif isinstance(step, PerContext):
            _run_per_context(emu, source, step, timeout, chat_start)


def _run_per_context(emu: Emulator, source: TestSource, step: PerContext, timeout: int, chat_start: int) -> None:
    """PackTestExecutor: the test command runs in each context of the prefix now; an ``await``
    whose condition does not hold yet (and every ``await delay``) registers a poll, and the polls
    are tried one at a time, the first after each tick, until none is left."""
    inner = step.step
    polls = []  # (context, poll)
    for ctx in source.contexts(step):
        if isinstance(inner, Dummy):
            _act(source, inner, ctx)
        elif isinstance(inner, Delay):
            polls.append((ctx, _countdown(inner.ticks)))
        elif _holds(source, inner, chat_start, ctx):
            continue
        elif inner.mode == "assert":
            raise _Verdict(FAILED, describe_failure(source, inner, chat_start, ctx), inner.loc.line)
        else:
            polls.append((ctx, lambda ctx=ctx: _holds(source, inner, chat_start, ctx)))
    while polls:
        ctx, poll = polls[0]
        waiting = (f"still in 'await delay {inner.ticks}'" if isinstance(inner, Delay)
                   else describe_failure(source, inner, chat_start, ctx))
        _tick_or_time_out(source, timeout, inner, f"{waiting} ({len(polls)} context(s) of the execute prefix waiting)")
        if poll():
            polls.pop(0)


def _countdown(ticks: int):
    """``await delay``'s poll (PackTestExecutor.await): true at the ``ticks``-th try."""
    left = [ticks]

    def poll() -> bool:
        left[0] -= 1
        return left[0] <= 0
    return poll


def _act(source: TestSource, step: Dummy, ctx: Context) -> None:
    """A dummy action run from ``ctx``: the game's refusal fails only the command (kept as a
    diagnostic); what the emulator cannot model fails the test."""
    try:
        source.dummies.run(step.command, ctx)
    except DummyFailure as refused:
        source.emu.state.error(f"{step.loc.path}:{step.loc.line}: {step.command.text}: {refused}")
    except Unsupported as reason:
        # the test cannot go on as the game would: inconclusive (failed under --allow-unmodelled)
        source.emu.state.error(f"{step.loc.path}:{step.loc.line}: {step.command.text}: not modelled: {reason}",
                               unmodelled=True)
        raise _Verdict(FAILED, f"{step.command.text}: not modelled: {reason}", step.loc.line) from None
    finally:  # a reward the action earned runs right after it, as after any test command
        source.emu.runtime.run_rewards()


def _holds(source: TestSource, step, chat_start: int, ctx: Context | None = None) -> bool:
    if isinstance(step, ChatCheck):
        return chat.holds(source.emu, step, chat_start, ctx or source.context())
    if isinstance(step, InsideCheck):
        return bool(_found_inside(source, step, ctx)) != step.negated
    return source.call(step.function, ctx) == 1


def _found_inside(source: TestSource, step: InsideCheck, ctx: Context | None) -> list[Entity]:
    """PackTest's ``entity SELECTOR inside``: the entities found that stand inside the test's bounds."""
    try:
        found = world_entities.select(source.emu.state, step.target, ctx or source.context())
    except CommandFailure as error:
        raise _Verdict(FAILED, error.message, step.loc.line) from None
    return [e for e in found if source.inside(e)]


def _tick_or_time_out(source: TestSource, timeout: int, step, waiting: str) -> None:
    if source.emu.ticks - source.started >= timeout:
        raise _Verdict(FAILED, f"Timed out after {timeout} ticks: {waiting}", step.loc.line)
    source.emu.tick()


def describe_failure(test: TestSource, check, chat_start: int = 0, ctx: Context | None = None) -> str:
    """PackTest's messages for failed score, chat, entity and data conditions (ScoreAssertion,
    ChatAssertion, EntityAssertion, DataAssertion); others name the condition."""
    expect = "Did not expect" if check.negated else "Expected"
    emu = test.emu
    if isinstance(check, ChatCheck):
        return chat.failure(emu, check, chat_start, ctx or test.context(), _sample)
    if isinstance(check, InsideCheck):  # AssertCommand.assertEntityInside
        if not check.negated:
            return f"Expected {check.selector} inside test"
        found = _found_inside(test, check, ctx)
        more = f" and {len(found) - 1} more" if len(found) > 1 else ""
        return f"Did not expect {check.selector} inside test, got {found[0].display_name}{more}"
    if check.per_context and _CONTEXT_BOUND.search(check.condition):  # the failing context is gone
        return f"{expect} {check.condition} (in every context of the execute prefix)"
    match = _SCORE_MATCHES.match(check.condition)
    if match:
        holder, objective, rng = match.groups()
        return f"{expect} score {holder} {objective} to match {rng}, found {_value(test, holder, objective)}"
    match = _SCORE_COMPARE.match(check.condition)
    if match:
        holder, objective, op, source, source_objective = match.groups()
        return (f"{expect} score {holder} {objective} {op} {source} {source_objective}, found "
                f"{_value(test, holder, objective)} {op} {_value(test, source, source_objective)}")
    match = _ENTITY.match(check.condition)
    if match:
        found = _entity_count(emu, match.group(1))
        if not check.negated:
            return f"Expected entity matching {match.group(1)}"
        return f"Did not expect entity matching {match.group(1)}" + (f", found {found}" if found is not None else "")
    match = _DATA.match(check.condition)
    if match:
        storage, path = match.groups()
        if check.negated:
            return f"Did not expect data at {path}"
        if storage and ":" not in storage:
            storage = "minecraft:" + storage
        found = to_snbt(emu.state.storage.get(storage, Compound())) if storage else None
        return f"Expected data at {path}" + (f", found {found}" if found is not None else "")
    return f"{expect} {check.condition}"


def _entity_count(emu: Emulator, selector: str) -> int | None:
    """How many entities ``selector`` finds from the world spawn (None when it needs a context
    the test source had, such as ``@s``)."""
    if selector.startswith("@s"):
        return None
    found = _entities(emu, selector)
    return None if found is None else len(found)


def _entities(emu: Emulator, selector: str) -> list[dict] | None:
    try:
        return emu.entities(selector)
    except Exception:  # a selector the world library cannot read from here: say nothing
        return None


def _sample(messages: list[str]) -> str:
    if not messages:
        return "nothing"
    shown = ", ".join('"' + (m[:80] + "…" if len(m) > 80 else m) + '"' for m in messages[:5])
    return shown + (f" and {len(messages) - 5} more" if len(messages) > 5 else "")


def _value(test: TestSource, holder: str, objective: str) -> str:
    """A score as the message shows it; a selector holder (``@s`` is the dummy) must find one entity."""
    if holder.startswith("@"):
        selector = test.dummy if holder == "@s" and test.dummy else holder
        found = (_entities(test.emu, selector) if selector != "@s" else None) or []
        if len(found) != 1:
            return "undefined"
        value = found[0]["scores"].get(objective)
    else:
        value = test.emu.score(holder, objective)
    return "undefined" if value is None else str(value)
