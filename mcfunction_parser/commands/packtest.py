"""PackTest's commands where any function runs them: ``assert``, ``fail`` and ``succeed``.

The PackTest mod registers them in the game's command dispatcher (AssertCommand, FailCommand,
SucceedCommand), so on a test server every function may use them: a library running a test's
callback (``function #lib:for_each {run: "assert score @s x matches 1"}``) runs one from a macro
line. Elsewhere the game does not know them. They are read while
:func:`mcfunction_parser.dialect.packtest_commands` is in effect (``dpemu test`` and the pytest
plugin load and run the packs inside it: :data:`PARSERS` go to ``dispatch.PACKTEST``); else they
are unknown commands, as in a game without PackTest.

- ``assert [not] CONDITION``: an ``execute if`` test, or PackTest's ``chat PATTERN [RECEIVERS]`` and
  ``entity TARGETS inside`` (kept as text: :class:`~mcfunction_parser.ast.PackTestAssert`).
- ``fail MESSAGE``: a text component; ``succeed``.

A test file's own lines are read by ``emulator.testing.testfile`` into steps, not by this module.
"""
from __future__ import annotations

from .. import ast
from ..arguments import text_component
from ..reader import Reader
from .execute import condition

_PACKTEST_ONLY = ("chat ",)  # conditions of PackTest's own, not execute's


def _succeed(r: Reader, loc) -> ast.Command:
    r.finish()
    return ast.PackTestSucceed.new(loc)


def _fail(r: Reader, loc) -> ast.Command:
    r.space("message")
    message = text_component(r)
    r.finish()
    return ast.PackTestFail.new(loc, message)


def _assert(r: Reader, loc) -> ast.Command:
    r.space("condition")
    negated = r.text.startswith("not ", r.pos)
    if negated:
        r.pos += len("not ")
    start = r.pos
    rest = r.text[start:]
    if rest.startswith(_PACKTEST_ONLY) or (rest.startswith("entity ") and rest.rstrip().endswith(" inside")):
        r.pos = r.end
        return ast.PackTestAssert.new(loc, negated, None, rest)
    test = condition(r, loc, False)
    r.finish()
    return ast.PackTestAssert.new(loc, negated, test, r.text[start:r.pos])


PARSERS = {"assert": _assert, "fail": _fail, "succeed": _succeed}
