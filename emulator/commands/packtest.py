"""PackTest's ``assert``, ``fail`` and ``succeed`` run by a function (a library running a test's
callback), as the PackTest mod runs them (AssertCommand.AssertCustomExecutor, FailCommand,
SucceedCommand): they reach the test whose commands run (its GameTestHelper, which PackTest keeps
on every command source made from the test's: ``state.test_helper``).

- ``assert [not] CONDITION``: held, the command succeeds with 1; failed, the test fails with
  PackTest's message for the condition, as a test file's ``assert`` line gets it
  (GameTestHelper.fail), at the test's line running then. The game's helper throws there and the
  rest of the test's commands of that tick do not run; here the command fails and they run on (the
  verdict is the same: the first failure stands). With no test running, PackTest's failed assert
  ends its function (frame.returnFailure): not modelled, said so.
- ``fail MESSAGE``: the test fails with the message's text, resolved for the source's entity
  (ComponentUtils.getResolvedComponent: selectors, scores, NBT); with no test, as a failed assert.
- ``succeed``: the test succeeds (GameTestHelper.succeed); with no test, nothing.

A test file's own lines are steps of :mod:`emulator.testing`, not these commands.
"""
from __future__ import annotations

from mcfunction_parser import ast

from emulator.world import text_components
from emulator.world.errors import CommandFailure, Unmodelled

from . import conditions, entities

_OUTSIDE = "PackTest's '{0}' failing outside a test, which ends its function (frame.returnFailure)"


def _assert(env, cmd: ast.PackTestAssert, ctx) -> int:
    if cmd.condition is None:
        raise Unmodelled(f"PackTest's 'assert {cmd.text}' run by a function (read as a test file's line only)")
    if isinstance(cmd.condition, ast.IfFunction):
        raise Unmodelled("PackTest's 'assert function' run by a function")
    if conditions.passes(env, cmd.condition, ctx) != cmd.negated:
        return 1
    helper = _helper(env, "assert")
    raise CommandFailure("dpemu.packtest.failed", helper.assert_failed(cmd.text, cmd.negated, ctx, env.frames(cmd)))


def fail_message(state, text: str, ctx) -> str:
    """PackTest's ``fail`` message: its text component resolved for the source's entity
    (FailCommand: ComponentUtils.getResolvedComponent), as plain text. A selector in it that must
    find one entity and does not fails the command (CommandFailure)."""
    def select(target) -> list:
        return entities.select(state, target, ctx)

    finder = text_components.finder(entities.parse_target, select)
    return text_components.resolved_plain(text, state, finder, entities.executor(state, ctx))


def _fail(env, cmd: ast.PackTestFail, ctx) -> int:
    message = fail_message(env.state, cmd.message, ctx)
    _helper(env, "fail").fail(message, env.frames(cmd))
    raise CommandFailure("dpemu.packtest.failed", message)


def _succeed(env, cmd: ast.PackTestSucceed, ctx) -> int:
    if env.state.test_helper is not None:
        env.state.test_helper.succeed()
    return 1


def _helper(env, name: str):
    """The running test's helper; failing with none is not modelled."""
    helper = env.state.test_helper
    if helper is None:
        raise Unmodelled(_OUTSIDE.format(name))
    return helper


HANDLERS = {ast.PackTestAssert: _assert, ast.PackTestFail: _fail, ast.PackTestSucceed: _succeed}
