"""Running test cases as the game test server runs them: one world (its packs loaded,
``#minecraft:load`` run), the batches in turn, the tests of a batch together; each test's steps in
order, ``await`` waiting for the world's next tick (``#minecraft:tick``, schedules) until the
test's timeout. Or each test alone in a fresh world (``isolate``)."""
from __future__ import annotations

import os
import random
import re
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass, replace
from pathlib import Path

from emulator.commands import entities as world_entities
from emulator.api import Emulator
from emulator.commands import stages
from emulator.commands.env import Env
from emulator.commands.packtest import fail_message
from emulator.world.errors import CommandFailure
from emulator.world.context import Context
from emulator.testing import batches, chat, environments
from emulator.testing.discovery import TestFile, selected
from emulator.testing.dummies import Dummies, DummyFailure, Unsupported
from emulator.testing.results import FAILED, INCONCLUSIVE, PASSED, Summary, TestResult
from emulator.testing.testfile import (
    ChatCheck, Check, Delay, Dummy, Fail, InsideCheck, PerContext, Run, Succeed, TestCase, read_test,
)
from emulator.world import players, structures
from emulator.world.blocks import BlockSpec, with_defaults
from emulator.world.entities import Entity
from mcfunction_parser.diagnostics import Diagnostic
from mcfunction_parser.nbt import Compound, String, to_snbt
from mcfunction_parser.dialect import packtest_commands
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
            packs.add_functions(case.functions)
        yield packs, _in_batches(cases)


def _in_batches(cases: list[TestCase]) -> list[TestCase]:
    """Order by batch (first appearance) and give every test of a batch the batch's
    @beforebatch/@afterbatch; a second, different one in a batch is an error of the test giving
    it (PackTest allows one per batch). They run once, before and after the batch (a test's own
    when tests run isolated)."""
    groups: dict[str, list[TestCase]] = {}
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
        groups.setdefault(d.batch, []).append(case)
    for batch, members in groups.items():
        for case in members:
            case.before_batch = hooks.get((batch, "@beforebatch"), (None, None))[1]
            case.after_batch = hooks.get((batch, "@afterbatch"), (None, None))[1]
    return [case for members in groups.values() for case in members]


def run_suite(files: list[TestFile], backend: str = "numba", pattern: str | None = None,
              on_result: Callable[[TestResult], None] | None = None, on_load=None, strict: bool = False,
              with_packs=(), together: bool = False, allow_unmodelled: bool = False, game_jar=None,
              isolate: bool = False) -> Summary:
    """Run every test in ``files`` (those whose id contains ``pattern``, case-insensitively);
    ``strict``: a runtime error during a test fails it; ``with_packs`` and ``together`` as
    :func:`load_suite`; ``allow_unmodelled``: a test that met something the emulator does not
    model passes or fails as it ran (else it is inconclusive); ``isolate``: each test in a world
    of its own (else as the game test server: see :func:`run_cases`). ``on_result`` sees each
    result as its test ends."""
    summary = Summary()
    with packtest_commands():  # a test server has the PackTest mod: its commands are known everywhere
        for packs, cases in load_suite(files, pattern, with_packs, together, game_jar):
            if on_load is not None:
                on_load(packs)
            for result in run_cases(packs, cases, backend, strict, allow_unmodelled, isolate):
                summary.results.append(result)
                if on_result is not None:
                    on_result(result)
    return summary


def run_cases(packs, cases: list[TestCase], backend: str = "numba", strict: bool = False,
              allow_unmodelled: bool = False, isolate: bool = False) -> Iterator[TestResult]:
    """Each case's result as its test ends. As the game test server runs them (default): one
    world for all, the batches one after another in the game's order, the tests of a batch
    placed side by side and run together (:mod:`emulator.testing.batches`), so what a test leaves
    outside its structure (scores, storage, entities, blocks) is there for the tests after it.
    ``isolate``: each test alone in a fresh world. A test that cannot be read fails at once."""
    for case in cases:
        if case.errors:
            yield _unreadable(case)
    runnable = [case for case in cases if not case.errors]
    if isolate:
        for case in runnable:
            yield from _World(packs, backend, strict, allow_unmodelled).run([batches.Batch(case.id, [case])])
    elif runnable:
        plan = batches.plan(runnable, packs.version >= _TEST_INSTANCES)
        yield from _World(packs, backend, strict, allow_unmodelled).run(plan)


def run_case(case: TestCase, packs, backend: str = "numba", strict: bool = False,
             allow_unmodelled: bool = False) -> TestResult:
    """One test alone in a fresh world."""
    with packtest_commands():
        return next(run_cases(packs, [case], backend, strict, allow_unmodelled, isolate=True))


def _unreadable(case: TestCase) -> TestResult:
    first = case.errors[0]
    return TestResult(case.id, case.path, FAILED, first.message, first.line, optional=case.directives.optional,
                      details=[d.format() for d in case.errors])


def fresh_world(packs, backend: str) -> Emulator:
    """An emulator on already parsed ``packs`` with an empty world, started with :func:`run_load`:
    the test server's world, made without structures (GameTestServer.WORLD_OPTIONS)."""
    emu = Emulator(backend=backend)
    emu.load_parsed(packs)
    emu.state.structures_generated = False
    return run_load(emu)


def run_load(emu: Emulator) -> Emulator:
    """Run ``#minecraft:load`` now (:meth:`Emulator.start`): a test starts in a running world."""
    emu.start()
    return emu


_TEST_INSTANCES = (1, 21, 5)  # the game's own test instances and environments (PackTest 2)
_CHUNK_WAIT = 20  # GameTestInfo.ticksToWaitForChunkLoading before 1.21.5
_STONE = BlockSpec("minecraft:stone", False, (), None)
_AIR = BlockSpec("minecraft:air", False, (), None)
_STRUCTURE_BLOCK = BlockSpec("minecraft:structure_block", False, (), None)
# StructureUtils.addCommandBlockAndButtonToStartTest: beside the structure block, to rerun the test by hand
_START_COMMAND_BLOCK = BlockSpec("minecraft:command_block", False, (), Compound(Command=String("test runclosest")))
_START_BUTTON = BlockSpec("minecraft:stone_button", False, (), None)


class _Running:
    """One test of the running batch: its source, its steps once started, its verdict."""

    def __init__(self, case: TestCase, source: TestSource) -> None:
        self.case, self.source = case, source
        self.template = None
        self.steps = None  # the test's steps (a generator yielding whenever it waits a tick)
        self.verdict: _Verdict | None = None
        self.diagnostics: list = []  # the runtime diagnostics that may bear on it
        self.log_start: int | None = None  # the world's log length when its first line ran
        self.clock = time.perf_counter()


class _World:
    """The game test server's world: loaded once (``#minecraft:load``, the first tick), then the
    batches run in it one after another (GameTestRunner.runBatch)."""

    def __init__(self, packs, backend: str, strict: bool, allow_unmodelled: bool) -> None:
        self.packs, self.strict, self.allow_unmodelled = packs, strict, allow_unmodelled
        self.test_instances = packs.version >= _TEST_INSTANCES
        self.emu = fresh_world(packs, backend)
        self.emu.tick()  # the rest of the server's first tick: GameTestServer.startTests runs after it
        self.dummies = Dummies(self.emu.state)
        self.grid = batches.Grid(TestSource.block_origin())
        self.seen = 0
        self.shared = self._new_diagnostics()  # the load's and the first tick's: every test's
        self.environments: list = []  # set up for the running batch, torn down when the next starts

    def _new_diagnostics(self) -> list:
        new = self.emu.diagnostics[self.seen:]
        self.seen = len(self.emu.diagnostics)
        return new

    def _charge(self, runs) -> None:
        """The diagnostics since the last charge go to ``runs`` (those running when they arose)."""
        new = self._new_diagnostics()
        for run in runs:
            run.diagnostics += new

    def run(self, plan: list[batches.Batch]) -> Iterator[TestResult]:
        for batch in plan:
            yield from self._run_batch(batch)
        self._end_environments()

    def _run_batch(self, batch: batches.Batch) -> Iterator[TestResult]:
        emu = self.emu
        runs = [_Running(case, TestSource(emu, self.dummies)) for case in batch.cases]
        for run in runs:  # GameTestRunner.createStructuresForBatch
            self._catch(run, self._prepare, run)
        first = batch.cases[0]
        if first.before_batch:
            emu.call(first.before_batch)
            self._charge(runs)
        self._end_environments()
        for environment_id in dict.fromkeys(case.directives.environment for case in batch.cases):
            users = [run for run in runs if run.case.directives.environment == environment_id]
            activation = self._catch(users, set_up_environment, emu, self.packs, environment_id)
            if activation is not None:
                self.environments.append(activation)
        emu.tick(2 if self.test_instances else _CHUNK_WAIT)
        self._charge(runs)
        for run in runs:  # GameTestInfo.startTest, in the ticker's order
            if run.verdict is None:
                if not self.test_instances and run.template is not None:
                    structures.place(emu.state, run.template, run.source.block_corner)
                run.source.started = emu.ticks
                run.log_start = len(emu.log)
                run.steps = self._steps(run)
        active = [run for run in runs if run.verdict is None]
        for run in runs:
            if run.verdict is not None:
                yield self._result(run)
        while active:
            for run in active:
                self._advance(run)
            for run in active:
                if run.verdict is not None:
                    yield self._result(run)
            active = [run for run in active if run.verdict is None]
            if active:
                emu.tick()
                self._charge(active)
        if first.after_batch:
            emu.call(first.after_batch)

    def _catch(self, runs, action, *args):
        """``action(*args)``; a verdict it raises is that of ``runs`` (one or a list)."""
        runs = runs if isinstance(runs, list) else [runs]
        try:
            return action(*args)
        except _Verdict as verdict:
            for run in runs:
                run.verdict = run.verdict or verdict
        finally:
            self._charge(runs)
        return None

    def _prepare(self, run: _Running) -> None:
        """The test's place on the grid, cleared, its structure (from 1.21.5; before, its structure
        block under the corner: the structure comes when the test starts) and the barriers round it
        (StructureGridSpawner.spawnStructure, GameTestInfo.prepareTestStructure)."""
        directives, source = run.case.directives, run.source
        run.template = read_template(self.packs, directives.template) if directives.template else None
        source.size = run.template.size if run.template is not None else (1, 1, 1)
        corner = self.grid.place(source.size)
        source.origin = tuple(float(c) for c in corner)
        self._clear(corner, source.size)
        if not self.test_instances:
            self._structure_block(corner)
        elif run.template is not None:
            structures.place(self.emu.state, run.template, corner)
        encase(self.emu, self.packs.version, corner, source.size, directives.sky_access)

    def _structure_block(self, corner) -> None:
        """Before 1.21.5 (GameTestInfo.prepareTestStructure): the structure block under the corner,
        a command block running ``test runclosest`` at it + (1, 0, -1) and a stone button north of
        that (StructureUtils.addCommandBlockAndButtonToStartTest, rotation none)."""
        blocks, version = self.emu.state.blocks, self.packs.version
        x, y, z = corner[0], corner[1] - 1, corner[2]
        blocks.place((x, y, z), _STRUCTURE_BLOCK)
        blocks.place((x + 1, y, z - 1), with_defaults(_START_COMMAND_BLOCK, version))
        blocks.place((x + 1, y, z - 2), with_defaults(_START_BUTTON, version))

    def _clear(self, corner, size) -> None:
        """StructureUtils.clearSpaceForStructure (and PackTest's StructureUtilsMixin for dummies)."""
        state = self.emu.state
        low, high = batches.cleared_box(corner, size)
        floor = corner[1] - 1
        for x in range(low[0], high[0] + 1):
            for y in range(low[1], high[1] + 1):
                for z in range(low[2], high[2] + 1):
                    state.blocks.place((x, y, z), _STONE if y < floor else _AIR)
        self._remove_entities(low, tuple(c + 1 for c in high))

    def _remove_entities(self, low, high) -> None:
        """Entities other than players in the box leave the world; dummies whose block is in it leave."""
        state = self.emu.state
        for entity in list(state.entities.entities):
            inside = all(lo <= p < hi for p, lo, hi in zip(entity.pos, low, high))
            if inside and entity.is_player and entity.uuid in self.dummies.spawns:
                players.leave(state, entity)
            elif inside and not entity.is_player:
                state.discard(entity)

    def _end_environments(self) -> None:
        for activation in reversed(self.environments):  # GameTestRunner.endCurrentEnvironment
            environments.tear_down(self.emu, activation)
        self.environments = []

    def _steps(self, run: _Running):
        run.source.dummy_entity = spawn_dummy(run.source, run.case)
        yield from _run_steps(self.emu, run.source, run.case)

    def _advance(self, run: _Running) -> None:
        """The test's next tick (GameTestInfo.tick): its steps until it waits again or ends."""
        try:
            next(run.steps)
        except StopIteration:
            run.verdict = _Verdict(PASSED)
        except _Verdict as verdict:
            run.verdict = verdict
        except Exception as error:  # an emulator bug fails this test, not the suite
            run.verdict = _Verdict(FAILED, f"internal error: {type(error).__name__}: {error}")
        finally:
            self._charge([run])
        if run.verdict is not None:
            self._finish(run)

    def _finish(self, run: _Running) -> None:
        """A test that ended: on success the entities in its bounds grown by a block are removed
        and its dummies there leave (GameTestInfo.succeed, PackTest's GameTestInfoMixin); from
        1.21.5 its barriers go (GameTestRunner's testCompleted: removeBarriers)."""
        source = run.source
        if run.verdict.status == PASSED:
            low = tuple(o - 1 for o in source.origin)
            self._remove_entities(low, tuple(o + s + 1 for o, s in zip(source.origin, source.size)))
        if self.test_instances:
            encase(self.emu, self.packs.version, source.block_corner, source.size, run.case.directives.sky_access,
                   remove=True)
        self._charge([run])

    def _result(self, run: _Running) -> TestResult:
        verdict, emu = run.verdict, self.emu
        result = TestResult(run.case.id, run.case.path, verdict.status, verdict.message, verdict.line,
                            optional=run.case.directives.optional)
        result.ticks = emu.ticks - run.source.started if run.steps is not None else 0
        if run.log_start is not None:
            result.log = [entry.line(emu.state.version) for entry in emu.log[run.log_start:]]
        result.seconds = time.perf_counter() - run.clock
        diagnostics = self.shared + run.diagnostics
        errors = [d for d in diagnostics if d.severity == "error"]
        unmodelled = [d for d in diagnostics if d.unmodelled]
        reason = None
        if result.status in (PASSED, FAILED) and unmodelled and not self.allow_unmodelled:
            # what the test saw may hang on the missing behaviour: neither a pass nor a failure
            reason = unmodelled[0]
            where = f"{reason.frames[-1].loc}: " if reason.frames else ""
            seen = f"the test {'passed' if result.status == PASSED else 'failed (' + result.message + ')'}"
            result.status, result.message = INCONCLUSIVE, f"{where}{reason.message}; {seen}"
            test_file = {shown_path(run.case.path), str(run.case.path)}
            in_test = [f.loc.line for f in reason.frames if f.loc.path in test_file]  # the test's line running then
            result.line = in_test[-1] if in_test else result.line
        elif result.status == PASSED and errors and self.strict:
            result.status, result.message = FAILED, f"{len(errors)} runtime error(s) during the test (--strict)"
        # shown with the test: every diagnostic when it did not pass, the runtime errors when it did;
        # the reason of an inconclusive one by its call stack alone (its message is the result's)
        shown = diagnostics if result.status != PASSED else errors
        details = (d.format() if d.message != getattr(reason, "message", None) else _call_stack(d) for d in shown)
        result.details = list(dict.fromkeys(text for text in details if text))
        return result


def _call_stack(diagnostic) -> str:
    """A diagnostic's call stack lines (``in FUNCTION at FILE:LINE:COL``), without its message."""
    return "\n".join(diagnostic.format().splitlines()[1:]).strip("\n")


def set_up_environment(emu: Emulator, packs, environment_id: str) -> environments.Activation:
    """The test environment set up (:mod:`emulator.testing.environments`); one that does not exist
    fails the tests using it, one of a type not modelled makes them inconclusive. From 1.21.5 the
    game sets up a batch's environment when the batch starts and tears it down when the next one
    starts (GameTestRunner.runBatch, endCurrentEnvironment); the emulator does the same before 1.21.5."""
    try:
        return environments.set_up(emu, environments.resolve(packs, environment_id))
    except environments.EnvironmentError as error:
        raise _Verdict(INCONCLUSIVE if error.unmodelled else FAILED, error.message) from None


_BARRIER = BlockSpec("minecraft:barrier", False, (), None)
_FLOORED_ENCASING = (1, 21, 5)  # TestInstanceBlockEntity (1.21.5+) adds a floor; StructureUtils before it


def encase(emu: Emulator, version, corner, size, sky_access: bool, remove: bool = False) -> None:
    """Barriers round the test structure whose corner is ``corner``, as the game encases a test:
    walls one block outside it, a ceiling unless the test has sky access, and from 1.21.5 a floor
    (TestInstanceBlockEntity.processStructureBoundary; StructureUtils.encaseStructure before).
    ``remove``: the barriers there become air again (TestInstanceBlockEntity.removeBarriers)."""
    x0, y0, z0 = corner
    low = (x0 - 1, y0 - 1 if version >= _FLOORED_ENCASING else y0, z0 - 1)
    high = (x0 + size[0], y0 + size[1], z0 + size[2])
    floor = version >= _FLOORED_ENCASING
    blocks = emu.state.blocks
    for x in range(low[0], high[0] + 1):
        for y in range(low[1], high[1] + 1):
            for z in range(low[2], high[2] + 1):
                wall = x in (low[0], high[0]) or z in (low[2], high[2]) or (floor and y == low[1])
                if not (wall or (y == high[1] and not sky_access)):
                    continue
                if not remove:
                    blocks.place((x, y, z), _BARRIER)
                elif blocks.get((x, y, z)).id == _BARRIER.id:
                    blocks.place((x, y, z), _AIR)


# the empty 1x1x1 structure a test without a template gets, by the names PackTest gives it
# (PackTestFunction: minecraft:empty; packtest:empty, which its jar ships)
EMPTY_TEMPLATES = frozenset({"minecraft:empty", "packtest:empty"})


def read_template(packs, template_id: str):
    """The test's structure (placed with its corner at the test source's block); None for the empty
    one when no pack has its own of that name (as a test without a template)."""
    data = structures.find_template(packs, template_id)
    if data is None and template_id in EMPTY_TEMPLATES:
        return None
    if data is None:
        missing = structures.template_file(packs, template_id)
        raise _Verdict(FAILED, f"Missing test structure: {template_id} (no {missing})")
    try:
        return structures.read_template(data)
    except structures.StructureError as error:
        raise _Verdict(FAILED, f"Test structure {template_id}: {error}") from None


class TestSource:
    """Where test commands run (PackTestExecutor.createCommandSourceStack): as the server, or as the
    test's dummy, at the test structure's corner (its place on the grid: the first test's is
    (0, 1, 0)). PackTest 1.x ran them at the test's structure block + (0, 1, 0), which is where the
    structure block places a structure, and PackTest 2 at the test origin, the same corner. The
    dummy stays the source's entity even after it left or respawned, as in PackTest."""

    ORIGIN = (0.0, 1.0, 0.0)  # the first test's corner

    def __init__(self, emu: Emulator, dummies: Dummies, size=(1, 1, 1)) -> None:
        self.emu, self.dummies = emu, dummies
        self.origin = self.ORIGIN
        self.size = size  # of the test structure, whose corner is origin
        self.dummy_entity: Entity | None = None
        self.helper = TestHelper(self)  # what PackTest's commands run by its functions reach
        self.started = emu.ticks  # the world's tick when its first line ran

    @classmethod
    def block_origin(cls) -> tuple[int, int, int]:
        return tuple(int(c) for c in cls.ORIGIN)

    @property
    def block_corner(self) -> tuple[int, int, int]:
        return tuple(int(c) for c in self.origin)

    def inside(self, entity: Entity) -> bool:
        """GameTestHelper.getBounds().inflate(1).contains(position): half-open on the far side."""
        return all(o - 1 <= p < o + s + 1 for p, o, s in zip(entity.pos, self.origin, self.size))

    @property
    def dummy(self) -> str | None:
        """The @dummy's UUID (None without one)."""
        return self.dummy_entity.uuid_string if self.dummy_entity is not None else None

    def context(self) -> Context:
        if self.dummy_entity is None:
            return Context(pos=self.origin)
        return replace(world_entities.entity_context(self.emu.state, self.dummy_entity), pos=self.origin)

    def call(self, function: str, context: Context | None = None) -> int | None:
        """Run ``function`` as the test runs its commands: PackTest's commands in the functions it
        calls reach this test's helper."""
        state = self.emu.state
        outer, state.test_helper = state.test_helper, self.helper
        try:
            return self.emu.runtime.call(function, context or self.context()).result
        finally:
            state.test_helper = outer

    def contexts(self, step: PerContext) -> list[Context]:
        """The contexts an execute prefix makes from the test source, each stage over all
        contexts before the next (ContextChain.executeAll): a condition through its generated
        function, the other stages through emulator.commands; a stage that fails drops its context. One
        the emulator cannot evaluate here fails the test saying so."""
        emu = self.emu
        env = Env(emu.state, emu.runtime.packs.functions, emu.runtime.packs.tags)
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


class TestHelper:
    """The test as PackTest's commands run by a function reach it (GameTestHelper.fail, succeed):
    the first failure stands."""

    def __init__(self, source: TestSource) -> None:
        self.source = source
        self.failure: str | None = None
        self.line: int | None = None  # the test's line that was running then
        self.succeeded = False

    def fail(self, message: str, frames: tuple = ()) -> None:
        """``frames``: the call stack of the failing command (its root, the test's function, first)."""
        if self.failure is None:
            self.failure = message
            self.line = frames[0].loc.line if frames else None

    def succeed(self) -> None:
        self.succeeded = True

    def assert_failed(self, condition: str, negated: bool, ctx: Context, frames: tuple = ()) -> str:
        """An ``assert [not] condition`` that did not hold in ``ctx``: the test fails with the
        message a test file's line gets (:func:`describe_failure`), which is returned."""
        message = describe_failure(self.source, _Condition(condition, negated), 0, ctx)
        self.fail(message, frames)
        return message


@dataclass(frozen=True)
class _Condition:
    """An assert's condition as :func:`describe_failure` reads a test file's check."""
    condition: str
    negated: bool
    per_context: bool = False


def _ended_by_commands(source: TestSource, step) -> bool:
    """Whether PackTest's commands run by the test's functions ended it: a failure raises its
    verdict, at the test's line running then (else the step's); True when one made it succeed."""
    helper = source.helper
    if helper.failure is not None:
        raise _Verdict(FAILED, helper.failure, helper.line or step.loc.line)
    return helper.succeeded


def spawn_dummy(source: TestSource, case: TestCase) -> Entity | None:
    """The @dummy player (PackTest's Dummy.createRandom: named Dummy100..Dummy999, drawn again while
    the name is online, ten tries; here drawn from a random seeded by the test id), at the
    directive's position relative to the test origin."""
    if case.directives.dummy is None:
        return None
    pos = _position(case.directives.dummy, source.origin)
    if pos is None:
        raise _Verdict(FAILED, "Failed to initialize test with dummy", 1)
    draw = random.Random(case.id)
    online = {p.player_name for p in source.emu.state.entities.players()}
    for _ in range(10):  # a name already online is drawn again, ten tries
        name = f"Dummy{draw.randrange(100, 1000)}"
        if name not in online:
            return source.dummies.spawn(name, pos, on_ground=True)  # PackTestFunction: setOnGround(true)
    raise _Verdict(FAILED, "Failed to spawn dummy with a random name", 1)


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


def _run_steps(emu: Emulator, source: TestSource, case: TestCase):
    """The test's lines in order (a generator: it yields whenever the test waits for the next tick)."""
    timeout = case.directives.timeout
    chat_start = len(emu.log)  # chat conditions see the messages since the test started
    for step in case.steps:
        if step.gate and source.call(step.gate) != 1:
            if _ended_by_commands(source, step):
                return
            continue
        if isinstance(step, Run):
            source.call(step.function)
        elif isinstance(step, (Check, ChatCheck, InsideCheck)) and step.mode == "assert":
            if not _holds(source, step, chat_start):
                raise _Verdict(FAILED, describe_failure(source, step, chat_start), step.loc.line)
        elif isinstance(step, (Check, ChatCheck, InsideCheck)):
            while not _holds(source, step, chat_start):
                yield from _wait(source, timeout, step, describe_failure(source, step, chat_start))
        elif isinstance(step, Delay):
            for _ in range(step.ticks):
                yield from _wait(source, timeout, step, f"still in 'await delay {step.ticks}'")
        elif isinstance(step, Fail):
            try:
                message = fail_message(emu.state, step.message, source.context())
            except CommandFailure:  # FailCommand ignores it: the line fails, the test goes on
                continue
            raise _Verdict(FAILED, message, step.loc.line)
        elif isinstance(step, Succeed):
            return
        elif isinstance(step, Dummy):
            _act(source, step, source.context())
        elif isinstance(step, PerContext):
            yield from _run_per_context(emu, source, step, timeout, chat_start)
        if _ended_by_commands(source, step):
            return


def _run_per_context(emu: Emulator, source: TestSource, step: PerContext, timeout: int, chat_start: int):
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
        yield from _wait(source, timeout, inner, f"{waiting} ({len(polls)} context(s) of the execute prefix waiting)")
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


def _wait(source: TestSource, timeout: int, step, waiting: str):
    """Wait for the next tick (the world ticks between two of the test's turns), or time out."""
    if source.emu.ticks - source.started >= timeout:
        raise _Verdict(FAILED, f"Timed out after {timeout} ticks: {waiting}", step.loc.line)
    yield


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
