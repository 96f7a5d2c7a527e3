"""Reading one PackTest test file into a :class:`TestCase`: its directives and its steps.

Ordinary lines are parsed by the project parser (in place, so every location is the file's own)
and grouped into generated functions, one per run of lines between test commands. The test
commands (``assert``, ``await``, ``fail``, ``succeed``, ``dummy``), also after
``execute ... run``, become steps. A condition is checked by a generated function
``execute if|unless COND run return 1`` / ``return 0``, so it means exactly what ``execute if``
means in the emulator. After an ``execute`` prefix, as PackTest runs the test command once per
context of the prefix: ``assert`` checks every context in one generated function; ``await``,
``assert chat`` and ``dummy`` become a :class:`PerContext` step (the runner makes the prefix's
contexts and runs the step in each); ``fail`` and ``succeed`` (which end the test at the first context) get a generated
gate ``PREFIX run return 1`` and run once when it passes.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

from emulator.commands import entities as world_entities
from emulator.testing.directives import Directives, apply, directive_match
from emulator.testing.dummies import DummyCommand, parse as parse_dummy
from mcfunction_parser.ast import Command, Condition, Function, MacroLine
from mcfunction_parser.diagnostics import Diagnostic, Loc
from mcfunction_parser.pack.text import split_lines
from mcfunction_parser.parse import parse_command, parse_function
from mcfunction_parser.reader import ParseError

GENERATED_NAMESPACE = "dpemu.test"
# the conditions of `execute if`, checked through the emulator, and PackTest's own `chat`
CONDITIONS = ("biome", "block", "blocks", "chat", "data", "dimension", "entity", "function", "items", "loaded",
              "predicate", "score")
_QUOTED = re.compile(r'"((?:[^"\\]|\\.)*)"|\'((?:[^\'\\]|\\.)*)\'')
_TEST_COMMAND = re.compile(r"(assert|await|fail|succeed|dummy)(?=\s|$)")
_EXECUTE_PREFIX = re.compile(r"(execute\s.*?)\s+run\s+(?=(?:assert|await|fail|succeed|dummy)(?:\s|$))")
_INSIDE = re.compile(r"entity\s+(.+?)\s+inside")
_TIME = re.compile(r"(\d+(?:\.\d+)?|\.\d+)([tsd]?)")
_TIME_UNITS = {"": 1, "t": 1, "s": 20, "d": 24000}


@dataclass(frozen=True)
class Step:
    loc: Loc
    gate: str | None  # generated function whose result 1 lets the step run


@dataclass(frozen=True)
class Run(Step):
    function: str


@dataclass(frozen=True)
class Check(Step):
    mode: str  # "assert" or "await"
    negated: bool
    condition: str
    function: str
    per_context: bool = False  # an ``execute ... run assert``: checked in every context of the prefix


@dataclass(frozen=True)
class ChatCheck(Step):
    """PackTest's ``chat PATTERN [RECEIVERS]``: a system message (tellraw ...) a player received
    since the test started matches the regular expression (searched, as Java's Matcher.find);
    see :mod:`emulator.testing.chat`."""

    mode: str
    negated: bool
    pattern: str
    receivers: object = None  # the RECEIVERS target (ast), None: every player's messages


@dataclass(frozen=True)
class InsideCheck(Step):
    """PackTest 2's ``entity SELECTOR inside``: an entity the selector finds stands inside the
    test's bounds grown by one block (AssertCommand.assertEntityInside)."""

    mode: str
    negated: bool
    selector: str  # as written, for the messages
    target: object  # the parsed selector


@dataclass(frozen=True)
class Delay(Step):
    ticks: int


@dataclass(frozen=True)
class Fail(Step):
    message: str  # a text component as written (resolved when the step runs)


@dataclass(frozen=True)
class Succeed(Step):
    pass


@dataclass(frozen=True)
class Dummy(Step):
    """PackTest's ``dummy <player> <action>`` (emulator.testing.dummies)."""

    command: DummyCommand


@dataclass(frozen=True)
class PerContext(Step):
    """``execute PREFIX run await|dummy ...``: ``step`` (without a gate) runs once in each context
    the prefix's ``stages`` make from the test source, in order (PackTestExecutor: each await
    registers its own poll, polled one after the other). ``conditions`` has, for each stage that
    is an ``if``/``unless`` test, a generated ``execute <test> run return 1`` that the runner
    calls per context (None for the other stages), so a test means what ``execute if`` means."""

    stages: tuple
    conditions: tuple
    step: Step


@dataclass
class TestCase:
    id: str
    path: str
    directives: Directives
    steps: list[Step] = field(default_factory=list)
    functions: dict[str, Function] = field(default_factory=dict)  # generated, by id
    before_batch: str | None = None  # generated function of @beforebatch
    after_batch: str | None = None  # generated function of @afterbatch
    errors: list[Diagnostic] = field(default_factory=list)  # the test cannot run


class _Builder:
    def __init__(self, case: TestCase, key: str, lines: list[str], version) -> None:
        self.case, self.key, self.lines, self.version = case, key, lines, version

    def function(self, commands: list[Command]) -> str:
        fid = f"{GENERATED_NAMESPACE}:{self.key}/{len(self.case.functions)}"
        last = max(c.loc.line for c in commands)
        self.case.functions[fid] = Function(fid, self.case.path, tuple(commands), last)
        return fid

    def command(self, text: str, line: int, text_col: int, shown_col: int) -> Command | None:
        """Parse generated ``text`` whose character ``text_col`` (1-based) stands for column
        ``shown_col`` of the file's line, so diagnostics point into the file."""
        cmd, diagnostics = parse_command(text, Loc(self.case.path, line, 1), self.version)
        for d in diagnostics:
            if d.severity == "error":
                col = max(1, (d.col or 1) - text_col + shown_col)
                self.error(d.message, line, col)
        return cmd if not any(d.severity == "error" for d in diagnostics) else None

    def error(self, message: str, line: int, col: int) -> None:
        self.case.errors.append(Diagnostic.at("error", message, Loc(self.case.path, line, col), self.lines[line - 1]))


def read_test(test_id: str, path: Path, shown: str, key: str, version) -> TestCase:
    """Read the test file ``path`` (shown as ``shown`` in messages); ``key`` makes the generated
    function ids unique."""
    case = TestCase(test_id, shown, Directives())
    try:
        lines = split_lines(path.read_text(encoding="utf-8-sig"))  # the game's line breaks
    except (OSError, UnicodeDecodeError) as error:
        case.errors.append(Diagnostic("error", f"cannot read the test file: {error}", shown))
        return case
    builder = _Builder(case, key, lines, version)
    test_lines = _read_header_and_classify(case, lines)
    ordinary = "".join(("" if i + 1 in test_lines else line) + "\n" for i, line in enumerate(lines))
    function, diagnostics = parse_function(ordinary, shown, f"{GENERATED_NAMESPACE}:{key}", version)
    case.errors.extend(d for d in diagnostics if d.severity == "error")
    case.errors.extend(case.directives.errors)
    by_line = {c.loc.line: c for c in function.commands if not isinstance(c, MacroLine)}
    for c in function.commands:
        if isinstance(c, MacroLine):
            builder.error("a macro line needs arguments, and a test runs without any", c.loc.line, c.loc.col)
    pending: list[Command] = []
    for number in range(1, len(lines) + 1):
        if number in by_line:
            pending.append(by_line[number])
        elif number in test_lines:
            if pending:
                case.steps.append(Run(pending[0].loc, None, builder.function(pending)))
                pending = []
            step = _test_step(builder, number, lines[number - 1])
            if step is not None:
                case.steps.append(step)
    if pending:
        case.steps.append(Run(pending[0].loc, None, builder.function(pending)))
    case.before_batch = _batch_command(builder, case.directives.before_batch)
    case.after_batch = _batch_command(builder, case.directives.after_batch)
    return case


def _batch_command(b: _Builder, given: tuple[str, Loc] | None) -> str | None:
    if given is None:
        return None
    text, loc = given
    shown_col = b.lines[loc.line - 1].index(text) + 1
    cmd = b.command(text, loc.line, 1, shown_col)
    return b.function([cmd]) if cmd is not None else None


def _read_header_and_classify(case: TestCase, lines: list[str]) -> set[int]:
    """Apply the header's directives; return the numbers of the lines holding test commands."""
    in_header = True
    test_lines: set[int] = set()
    for number, line in enumerate(lines, 1):
        in_header = in_header and line.startswith("#")
        match = directive_match(line) if in_header else None
        if match:
            apply(case.directives, match, Loc(case.path, number, 1), line)
        stripped = line.strip()
        is_command = stripped and not stripped.startswith("#")
        if is_command and (_TEST_COMMAND.match(stripped) or _EXECUTE_PREFIX.match(stripped)):
            test_lines.add(number)
    return test_lines


def _test_step(b: _Builder, number: int, line: str) -> Step | None:
    col = len(line) - len(line.lstrip()) + 1
    text = line.strip()
    gate = prefix_text = stages = None
    prefix = _EXECUTE_PREFIX.match(text)
    if prefix:
        prefix_text = prefix.group(1)
        gate_cmd = b.command(prefix_text + " run return 1", number, 1, col)
        if gate_cmd is None:
            return None
        col += prefix.end()
        text = text[prefix.end():]
        if text.split(" ", 1)[0] in ("fail", "succeed"):
            gate = b.function([gate_cmd])
        else:
            stages = gate_cmd.subcommands
    step = _plain_step(b, number, line, text, col, gate, prefix_text)
    if stages is None or step is None or getattr(step, "per_context", False):
        return step
    conditions = _stage_conditions(b, stages, prefix_text, number, col - prefix.end())
    return None if conditions is None else PerContext(step.loc, None, stages, conditions, step)


def _stage_conditions(b: _Builder, stages: tuple, prefix: str, number: int, col: int) -> tuple | None:
    """Per stage of an execute prefix, a generated function testing it when it is a condition."""
    ends = [s.loc.col - 1 for s in stages[1:]] + [len(prefix)]
    out = []
    for stage, end in zip(stages, ends):
        if not isinstance(stage, Condition):
            out.append(None)
            continue
        head = "execute "
        start = stage.loc.col - 1
        cmd = b.command(head + prefix[start:end].strip() + " run return 1", number, len(head) + 1, col + start)
        if cmd is None:
            return None
        out.append(b.function([cmd]))
    return tuple(out)


def _plain_step(b: _Builder, number: int, line: str, text: str, col: int, gate, prefix_text) -> Step | None:
    loc = Loc(b.case.path, number, col)
    word, _, rest = text.partition(" ")
    rest_col = min(col + len(word) + 1 + (len(rest) - len(rest.lstrip())), len(line) + 1)
    rest = rest.strip()
    if word == "succeed":
        return Succeed(loc, gate) if not rest else _bad(b, "succeed takes no arguments", number, rest_col)
    if word == "fail":
        return Fail(loc, gate, rest) if rest else _bad(b, "fail: expected a message", number, rest_col)
    if word == "dummy":
        try:
            return Dummy(loc, gate, parse_dummy(text, loc, b.version))
        except ParseError as error:
            return _bad(b, error.message, number, col + error.pos)
    first = rest.split(" ", 1)[0]
    if word == "await" and first in ("delay", "for"):  # "await for" in PackTest before 1.7
        return _delay(b, loc, gate, rest[len(first):].strip(), number, rest_col + len(first) + 1)
    negated = rest.split(" ", 1)[0] == "not"
    if negated:
        rest_col += len("not")
        rest = rest[len("not"):]
        rest_col += len(rest) - len(rest.lstrip())
        rest = rest.strip()
    kind = rest.split(" ", 1)[0]
    inside = _INSIDE.fullmatch(rest)
    if inside:
        return _inside(b, loc, gate, word, negated, inside.group(1), number, rest_col + len("entity "))
    if prefix_text and word == "assert" and kind in CONDITIONS and kind != "chat":
        return _check_each(b, loc, prefix_text, negated, rest, number, rest_col)
    return _check(b, loc, gate, word, negated, rest, number, rest_col)


def _check_each(b: _Builder, loc: Loc, prefix: str, negated: bool, condition: str, number: int, col: int):
    """``execute PREFIX run assert [not] COND`` asserts in every context the prefix makes (none: it
    passes), as PackTest runs the assert command per context: the generated function returns 0 at
    the first context where the assertion fails."""
    head = f"{prefix} {'if' if negated else 'unless'} "
    cmd = b.command(head + condition + " run return 0", number, len(head) + 1, col)
    passed = b.command("return 1", number, 1, col)
    if cmd is None or passed is None:
        return None
    return Check(loc, None, "assert", negated, condition, b.function([cmd, passed]), per_context=True)


def _check(b: _Builder, loc: Loc, gate, mode: str, negated: bool, condition: str, number: int, col: int):
    kind = condition.split(" ", 1)[0]
    if kind not in CONDITIONS:
        return _bad(b, f"{mode}: unknown condition {kind!r}: expected one of " + ", ".join(CONDITIONS), number, col)
    if kind == "chat":
        return _chat(b, loc, gate, mode, negated, condition[len("chat"):].strip(), number, col + len("chat "))
    head = f"execute {'unless' if negated else 'if'} "
    cmd = b.command(head + condition + " run return 1", number, len(head) + 1, col)
    fallback = b.command("return 0", number, 1, col)
    if cmd is None or fallback is None:
        return None
    return Check(loc, gate, mode, negated, condition, b.function([cmd, fallback]))


def _chat(b: _Builder, loc: Loc, gate, mode: str, negated: bool, text: str, number: int, col: int):
    """``chat PATTERN`` where PATTERN is a brigadier string: a quoted string or one word."""
    quoted = _QUOTED.match(text)
    if quoted:
        body = quoted.group(1) if quoted.group(1) is not None else quoted.group(2)
        bad = next((m for m in re.finditer(r"\\(.)", body) if m.group(1) not in "\\\"'"), None)
        if bad:  # StringReader.readStringUntil accepts only \\, \" and \'
            return _bad(b, f"Invalid escape sequence '{bad.group()}' in quoted string", number, col + 1 + bad.start())
        pattern = re.sub(r"\\(.)", r"\1", body)
        rest = text[quoted.end():].strip()
    else:
        pattern, _, rest = text.partition(" ")
    if not pattern:
        return _bad(b, f"{mode} chat: expected a pattern", number, col)
    receivers = None
    if rest:
        try:
            receivers = world_entities.parse_target(rest)
        except ValueError as error:
            return _bad(b, f"{mode} chat: receivers: {error}", number, col + len(text) - len(rest))
    try:
        re.compile(pattern)
    except re.error:
        return _bad(b, f"Invalid pattern '{pattern}'", number, col)
    return ChatCheck(loc, gate, mode, negated, pattern, receivers)


def _inside(b: _Builder, loc: Loc, gate, mode: str, negated: bool, selector: str, number: int, col: int):
    try:
        target = world_entities.parse_target(selector)
    except ValueError as error:
        return _bad(b, f"{mode} entity: {error}", number, col)
    return InsideCheck(loc, gate, mode, negated, selector, target)


def _delay(b: _Builder, loc: Loc, gate, text: str, number: int, col: int):
    match = _TIME.fullmatch(text)
    if not match:
        return _bad(b, f"await delay: expected a time such as 20, 20t, 1s or 1d, got {text!r}", number, col)
    # TimeArgument: round(value * unit ticks)
    return Delay(loc, gate, round(float(match.group(1)) * _TIME_UNITS[match.group(2)]))


def _bad(b: _Builder, message: str, number: int, col: int) -> None:
    b.error(message, number, col)
    return None
