"""``scoreboard`` commands, following ScoreboardCommand and OperationArgument (decompiled 1.21).

Each function runs one command for one context and returns its int result, or raises
:class:`CommandFailure`. Arguments are read in the order ScoreboardCommand's ``executes``
lambdas pass them (targets before their objective, then the operation's sources and theirs).
"""
from __future__ import annotations

from typing import Callable

from emulator.world.semantics import floor_mod, wrap32
from mcfunction_parser import ast
from mcfunction_parser.arguments import score_holder
from mcfunction_parser.reader import ParseError, Reader

from emulator.world.errors import CommandFailure
from .holders import holder_names, objective, single_holder, writable_objective


def get_or_create(board, holder: str, obj: str) -> int:
    """Scoreboard.getOrCreatePlayerScore: an unset score becomes 0 and is now set."""
    value = board.get(holder, obj)
    if value is None:
        board.set(holder, obj, 0)
        return 0
    return value


def _alive_count(env) -> int:
    return int(env.state.scoreboard.alive.sum())


# ---------------------------------------------------------------------- objectives
def objectives_add(env, cmd: ast.ObjectivesAdd, ctx) -> int:
    if not env.state.scoreboard.add_objective(cmd.objective, cmd.criterion, cmd.display_name):
        raise CommandFailure("commands.scoreboard.objectives.add.duplicate")
    return _alive_count(env)


def objectives_remove(env, cmd: ast.ObjectivesRemove, ctx) -> int:
    env.state.scoreboard.remove_objective(objective(env, cmd.objective))
    return _alive_count(env)


def objectives_modify(env, cmd: ast.ObjectivesModify | ast.ObjectivesSetdisplay, ctx) -> int:
    """``modify`` and ``setdisplay``: the objective must exist; nothing the emulator keeps changes."""
    if cmd.objective is not None:
        objective(env, cmd.objective)
    return 0


def objectives_list(env, cmd: ast.ObjectivesList, ctx) -> int:
    return _alive_count(env)


# ---------------------------------------------------------------------- players
def players_set(env, cmd: ast.ScoreSet, ctx) -> int:
    """setScore: the result is value x targets; addScore/removeScore: the (int) sum of the new values."""
    names = holder_names(env, cmd.targets, ctx)
    obj = writable_objective(env, cmd.objective)
    board = env.state.scoreboard
    if cmd.action == "set":
        for name in names:
            board.set(name, obj, cmd.value)
        return wrap32(cmd.value * len(names))
    step = cmd.value if cmd.action == "add" else -cmd.value
    total = 0
    for name in names:
        old = get_or_create(board, name, obj)
        new = env.arith(cmd.action, old, cmd.value, old + step)
        board.set(name, obj, new)
        total = wrap32(total + new)
    return total


def players_reset(env, cmd: ast.ScoreReset, ctx) -> int:
    names = holder_names(env, cmd.targets, ctx)
    obj = None if cmd.objective is None else objective(env, cmd.objective)
    for name in names:
        env.state.scoreboard.reset(name, obj)
    return len(names)


def players_get(env, cmd: ast.ScoreGet, ctx) -> int:
    name = single_holder(env, cmd.target, ctx)
    obj = objective(env, cmd.objective)
    value = env.state.scoreboard.get(name, obj)
    if value is None:
        raise CommandFailure("commands.scoreboard.players.get.null", obj, name)
    return value


def players_list(env, cmd: ast.ScoreList, ctx) -> int:
    """The number of holders tracked, or of one holder's scores."""
    board = env.state.scoreboard
    if cmd.target is None:
        return len(board.tracked_holders())
    name = single_holder(env, cmd.target, ctx)
    return sum(1 for obj in board.objectives if board.get(name, obj) is not None)


def players_enable(env, cmd: ast.ScoreEnable, ctx) -> int:
    """ScoreboardCommand.enableTrigger: unlock each holder's score (created as 0 if missing); the
    count of scores that were locked; none fails."""
    names = holder_names(env, cmd.targets, ctx)
    obj = objective(env, cmd.objective)
    board = env.state.scoreboard
    if board.criteria[board.objective_ids[obj]] != "trigger":
        raise CommandFailure("commands.scoreboard.players.enable.invalid")
    unlocked = sum(board.enable(name, obj) for name in names)
    if unlocked == 0:
        raise CommandFailure("commands.scoreboard.players.enable.failed")
    return unlocked


def players_display(env, cmd: ast.ScoreDisplay, ctx) -> int:
    """``scoreboard players display name|numberformat TARGETS OBJECTIVE ...`` (setScoreDisplay,
    setScoreNumberFormat): each target's score is fetched get-or-create (an unset one becomes 0,
    as for ``set``) before its display name or number format changes, which the emulator does not
    keep; the result is the number of targets. The objective is read with getObjective (read-only
    ones too), after the targets."""
    holder, name = display_arguments(cmd)
    targets = holder_names(env, holder, ctx)
    objective(env, name)
    for target in targets:
        get_or_create(env.state.scoreboard, target, name)
    return len(targets)


def display_arguments(cmd: ast.ScoreDisplay) -> tuple[object, str]:
    """The TARGETS (a score holder node) and OBJECTIVE of the text the parser kept after ``display``."""
    kind, _, rest = cmd.text.partition(" ")
    reader = Reader(rest, cmd.loc, (1, 21, 0))
    try:
        holder = score_holder(reader)
    except ParseError:
        raise CommandFailure("command.unknown.argument") from None
    name = rest[reader.pos:].split(maxsplit=1)
    if not name:
        raise CommandFailure("command.unknown.argument")
    return holder, name[0]


def players_operation(env, cmd: ast.ScoreOperation, ctx) -> int:
    """performOperation: for each target (get-or-create), for each source (get-or-create), apply;
    the result is the (int) sum of the targets' new values.

    A division by zero fails the command where it happens: earlier pairs stay applied and both
    scores of the failing pair have been created.
    """
    board = env.state.scoreboard
    targets = holder_names(env, cmd.targets, ctx)
    obj = writable_objective(env, cmd.objective)
    sources = holder_names(env, cmd.sources, ctx)
    src_obj = objective(env, cmd.source_objective)
    total = 0
    for target in targets:
        get_or_create(board, target, obj)
        for source in sources:
            b = get_or_create(board, source, src_obj)
            a = board.get(target, obj)
            if cmd.op == "><":  # OperationArgument: the target takes the source's value first
                board.set(target, obj, b)
                board.set(source, src_obj, a)
            else:
                board.set(target, obj, _apply(env, cmd.op, a, b))
        total = wrap32(total + board.get(target, obj))
    return total


def _apply(env, op: str, a: int, b: int) -> int:
    """OperationArgument's SimpleOperation ``op``; the arithmetic wraps as Java's int does."""
    if op in ("/=", "%=") and b == 0:
        raise CommandFailure("arguments.operation.div0", report=True)
    exact = _OPERATIONS[op](a, b)
    if op in _WRAPPING:
        return env.arith(op, a, b, exact)
    return exact


_OPERATIONS: dict[str, Callable[[int, int], int]] = {
    "=": lambda a, b: b,
    "+=": lambda a, b: a + b,
    "-=": lambda a, b: a - b,
    "*=": lambda a, b: a * b,
    "/=": lambda a, b: a // b,  # Mth.floorDiv: only MIN / -1 leaves the int range (wraps to MIN)
    "%=": floor_mod,
    "<": min,
    ">": max,
}
_WRAPPING = ("+=", "-=", "*=", "/=")

HANDLERS = {
    ast.ObjectivesAdd: objectives_add,
    ast.ObjectivesRemove: objectives_remove,
    ast.ObjectivesModify: objectives_modify,
    ast.ObjectivesSetdisplay: objectives_modify,
    ast.ObjectivesList: objectives_list,
    ast.ScoreSet: players_set,
    ast.ScoreReset: players_reset,
    ast.ScoreGet: players_get,
    ast.ScoreEnable: players_enable,
    ast.ScoreList: players_list,
    ast.ScoreDisplay: players_display,
    ast.ScoreOperation: players_operation,
}
