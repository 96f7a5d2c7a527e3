"""``scoreboard`` commands, following ScoreboardCommand and OperationArgument (1.21).

Each function runs one command for one source and returns its int result, or raises
:class:`CommandFailure`. ``env`` is the interpreter: ``env.state`` and ``env.arith`` (wrapping
arithmetic that reports overflows to the sanitizer).
"""
from __future__ import annotations

from emulator.world.semantics import floor_div, floor_mod, wrap32
from emulator.world import server_commands
from mcfunction_parser import ast

from .data import world_failures
from .failure import CommandFailure, unknown_objective
from .holders import holder_names, single_holder
from .source import Source


def objective(env, name: str) -> str:
    """ObjectiveArgument.getObjective: the objective must exist."""
    if not env.state.scoreboard.exists(name):
        raise unknown_objective(name)
    return name


def writable_objective(env, name: str) -> str:
    """ObjectiveArgument.getWritableObjective: exists and is not read-only (``health`` ...)."""
    objective(env, name)
    if not env.state.scoreboard.is_writable(name):
        raise CommandFailure(f"Scoreboard objective '{name}' is read-only")
    return name


def get_or_create(env, holder: str, obj: str) -> int:
    """Scoreboard.getOrCreatePlayerScore: an unset score becomes 0 and is now set."""
    board = env.state.scoreboard
    value = board.get(holder, obj)
    if value is None:
        board.set(holder, obj, 0)
        return 0
    return value


def _alive_count(env) -> int:
    board = env.state.scoreboard
    return int(board.alive[: len(board.objectives)].sum())


def objectives_add(env, cmd: ast.ObjectivesAdd, source: Source, where) -> int:
    if not env.state.scoreboard.add_objective(cmd.objective, cmd.criterion, cmd.display_name):
        raise CommandFailure("An objective already exists by that name")
    return _alive_count(env)


def objectives_remove(env, cmd: ast.ObjectivesRemove, source: Source, where) -> int:
    env.state.scoreboard.remove_objective(objective(env, cmd.objective))
    return _alive_count(env)


def objectives_modify(env, cmd: ast.ObjectivesModify, source: Source, where) -> int:
    objective(env, cmd.objective)
    return 0


def objectives_setdisplay(env, cmd: ast.ObjectivesSetdisplay, source: Source, where) -> int:
    if cmd.objective is not None:
        objective(env, cmd.objective)
    return 0


def objectives_list(env, cmd: ast.ObjectivesList, source: Source, where) -> int:
    return _alive_count(env)


def players_set(env, cmd: ast.ScoreSet, source: Source, where) -> int:
    """set: result value x targets; add/remove: the wrapping sum of the new values."""
    names = holder_names(cmd.targets, source, env.state.scoreboard)
    obj = writable_objective(env, cmd.objective)
    board = env.state.scoreboard
    if cmd.action == "set":
        for name in names:
            board.set(name, obj, cmd.value)
        return wrap32(cmd.value * len(names))
    total = 0
    for name in names:
        old = get_or_create(env, name, obj)
        if cmd.action == "add":
            new = env.arith("add", old, cmd.value, old + cmd.value, source, where)
        else:
            new = env.arith("remove", old, cmd.value, old - cmd.value, source, where)
        board.set(name, obj, new)
        total = wrap32(total + new)
    return total


def players_reset(env, cmd: ast.ScoreReset, source: Source, where) -> int:
    names = holder_names(cmd.targets, source, env.state.scoreboard)
    obj = None if cmd.objective is None else objective(env, cmd.objective)
    for name in names:
        env.state.scoreboard.reset(name, obj)
    return len(names)


def players_get(env, cmd: ast.ScoreGet, source: Source, where) -> int:
    name = single_holder(cmd.target, source, env.state.scoreboard)
    obj = objective(env, cmd.objective)
    value = env.state.scoreboard.get(name, obj)
    if value is None:
        raise CommandFailure(f"Can't get value of {obj} for {name}; none is set")
    return value


def players_enable(env, cmd: ast.ScoreEnable, source: Source, where) -> int:
    names = holder_names(cmd.targets, source, env.state.scoreboard)
    obj = objective(env, cmd.objective)
    with world_failures():
        return server_commands.enable_command(env.state, names, obj)


def players_list(env, cmd: ast.ScoreList, source: Source, where) -> int:
    board = env.state.scoreboard
    if cmd.target is None:
        return len(board.tracked_holders())
    name = single_holder(cmd.target, source, board)
    return sum(1 for obj in board.objectives if board.get(name, obj) is not None)


def players_display(env, cmd: ast.ScoreDisplay, source: Source, where) -> int:
    with world_failures():
        return server_commands.display_command(
            env.state, cmd, lambda holder: holder_names(holder, source, env.state.scoreboard),
            lambda name: objective(env, name))


def players_operation(env, cmd: ast.ScoreOperation, source: Source, where) -> int:
    """For each target, for each source: get-or-create both, apply; result: sum of targets' values.

    A division by zero fails the command where it happens: earlier pairs stay applied and both
    scores of the failing pair have been created.
    """
    board = env.state.scoreboard
    targets = holder_names(cmd.targets, source, board)
    obj = writable_objective(env, cmd.objective)
    sources = holder_names(cmd.sources, source, board)
    src_obj = objective(env, cmd.source_objective)
    total = 0
    for target in targets:
        get_or_create(env, target, obj)
        for other in sources:
            b = get_or_create(env, other, src_obj)
            a = board.get(target, obj)
            if cmd.op == "><":
                board.set(target, obj, b)
                board.set(other, src_obj, a)
            else:
                board.set(target, obj, _apply(env, cmd.op, a, b, source, where))
        total = wrap32(total + board.get(target, obj))
    return total


def _apply(env, op: str, a: int, b: int, source: Source, where) -> int:
    if op == "=":
        return b
    if op == "<":
        return min(a, b)
    if op == ">":
        return max(a, b)
    if op == "+=":
        return env.arith(op, a, b, a + b, source, where)
    if op == "-=":
        return env.arith(op, a, b, a - b, source, where)
    if op == "*=":
        return env.arith(op, a, b, a * b, source, where)
    if b == 0:
        raise CommandFailure("Cannot divide by zero", report=True)
    if op == "/=":
        # floorDiv wraps only for MIN / -1
        env.arith(op, a, b, a // b, source, where)
        return floor_div(a, b)
    if op == "%=":
        return floor_mod(a, b)
    raise CommandFailure(f"Invalid operation {op}")


HANDLERS = {
    ast.ObjectivesAdd: objectives_add,
    ast.ObjectivesRemove: objectives_remove,
    ast.ObjectivesModify: objectives_modify,
    ast.ObjectivesSetdisplay: objectives_setdisplay,
    ast.ObjectivesList: objectives_list,
    ast.ScoreSet: players_set,
    ast.ScoreReset: players_reset,
    ast.ScoreGet: players_get,
    ast.ScoreEnable: players_enable,
    ast.ScoreList: players_list,
    ast.ScoreDisplay: players_display,
    ast.ScoreOperation: players_operation,
}
