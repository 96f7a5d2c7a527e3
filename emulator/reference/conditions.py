"""``execute if|unless ...`` tests (ExecuteCommand.addConditionals), as a stage or as the final command.

As a stage, a context passes when the test's outcome differs from ``negated``. As the final
command (``execute if score ...`` without ``run``): ``if`` passes with 1 (``entity``, ``data``:
the count), ``unless`` passes with 1, and a failing test fails the command ("Test failed").
"""
from __future__ import annotations

from mcfunction_parser import ast

from . import data, entities
from .failure import CommandFailure, unsupported
from .holders import single_holder
from .scoreboard import objective
from .source import Source

_COMPARE = {
    "<": lambda a, b: a < b,
    "<=": lambda a, b: a <= b,
    "=": lambda a, b: a == b,
    ">=": lambda a, b: a >= b,
    ">": lambda a, b: a > b,
}


def count(env, cond: ast.Condition, source: Source) -> int:
    """How many things the test found: 0 or 1 for yes/no tests, a count for ``entity`` and ``data``."""
    if isinstance(cond, ast.IfScore):
        return int(_score_compare(env, cond, source))
    if isinstance(cond, ast.IfScoreMatches):
        board = env.state.scoreboard
        holder = single_holder(cond.target, source, board)
        value = board.get(holder, objective(env, cond.objective))
        # ExecuteCommand.checkScore: an unset score never matches
        return int(value is not None and cond.range.contains(value))
    if entities.world.is_world_condition(cond):  # entity, block, entity or block data
        return entities.condition_count(cond, source)
    if isinstance(cond, ast.IfData):
        return data.count_matching(env, cond)
    if isinstance(cond, ast.IfDimension):
        return int(source.context.dimension == cond.dimension)
    raise unsupported(f"'{type(cond).__name__}'")


def passes(env, cond: ast.Condition, source: Source) -> bool:
    return (count(env, cond, source) > 0) != cond.negated


def run_as_command(env, cond: ast.Condition, source: Source, where) -> int:
    found = count(env, cond, source)
    if not cond.negated:
        if found > 0:
            return found
        raise CommandFailure("Test failed")
    if found == 0:
        return 1
    if isinstance(cond, (ast.IfEntity, ast.IfData)):
        raise CommandFailure(f"Test failed, count: {found}")
    raise CommandFailure("Test failed")


def _score_compare(env, cond: ast.IfScore, source: Source) -> bool:
    board = env.state.scoreboard
    target = single_holder(cond.target, source, board)
    obj = objective(env, cond.objective)
    other = single_holder(cond.source, source, board)
    src_obj = objective(env, cond.source_objective)
    a = board.get(target, obj)
    b = board.get(other, src_obj)
    # ExecuteCommand.checkScore: false when either score is unset
    return a is not None and b is not None and _COMPARE[cond.op](a, b)

