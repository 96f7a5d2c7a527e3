"""``execute if|unless ...`` tests (ExecuteCommand.addConditionals, decompiled 1.21), as a stage or
as the final command.

:func:`count` is what a test finds: 0 or 1 for yes/no tests, a count for ``entity``, ``data`` and
``blocks``. As a stage, a context passes when ``count > 0`` differs from ``negated``. As the final
command (``execute if score ...`` without ``run``, :func:`as_command`): ``if`` passes with the
count, ``unless`` with 1, and a failing test fails the command ("Test failed"; an ``unless`` of a
counting test says the count, createNumericConditionalHandler / checkUnlessRegions).
"""
from __future__ import annotations

from mcfunction_parser import ast

from emulator.world import predicates, stopwatches
from emulator.world.loot_context import LootContext
from mcfunction_parser.pack import conditions as pack_conditions

from . import blocks, data, entities, items
from .entities import executor
from emulator.world.errors import CommandFailure, Unmodelled
from .holders import objective, single_holder

_COMPARE = {
    "<": lambda a, b: a < b,
    "<=": lambda a, b: a <= b,
    "=": lambda a, b: a == b,
    ">=": lambda a, b: a >= b,
    ">": lambda a, b: a > b,
}
_COUNTING = (ast.IfEntity, ast.IfData, ast.IfBlocks, ast.IfItems)


def count(env, cond: ast.Condition, ctx) -> int:
    """How many things the test found (0: it fails)."""
    if isinstance(cond, ast.IfScore):
        return int(_score_compare(env, cond, ctx))
    if isinstance(cond, ast.IfScoreMatches):
        return int(_score_matches(env, cond, ctx))
    if isinstance(cond, ast.IfEntity):
        return len(entities.select(env.state, cond.targets, ctx))
    if isinstance(cond, ast.IfData):
        return data.count_matching(env, cond, ctx)
    if isinstance(cond, ast.IfBlock):
        return blocks.if_block(env, cond, ctx)
    if isinstance(cond, ast.IfBlocks):
        return blocks.if_blocks(env, cond, ctx)
    if isinstance(cond, ast.IfItems):
        return items.count_items(env, cond, ctx)
    if isinstance(cond, ast.IfDimension):
        env.state.entities.table.levels.level_id(cond.dimension)  # DimensionArgument.getDimension: an unknown one fails
        return int(cond.dimension == ctx.dimension)
    if isinstance(cond, ast.IfPredicate):
        return int(if_predicate(env, cond.predicate, ctx))
    if isinstance(cond, ast.IfBiome):
        return blocks.if_biome(env, cond, ctx)
    if isinstance(cond, ast.IfLoaded):
        return blocks.if_loaded(env, cond, ctx)
    if isinstance(cond, ast.IfStopwatch):  # ExecuteCommand.checkStopwatch: MinMaxBounds.Doubles.matches
        return int(cond.range.contains(stopwatches.elapsed_seconds(env.state, cond.stopwatch)))
    raise Unmodelled(f"the condition '{type(cond).__name__}'")


def if_predicate(env, predicate: str, ctx) -> bool:
    """ExecuteCommand.checkCustomPredicate: the predicate (an id, or inline ``{...}``) with the
    COMMAND parameters: the context's position as origin and its entity as ``this``. An unknown id
    fails the command (ResourceOrIdArgument since 1.20.5, ResourceLocationArgument before)."""
    state = env.state
    version = state.version
    if predicate[:1] in "{[":
        try:
            value = pack_conditions.parse_inline(predicate)
        except ValueError as error:
            raise CommandFailure("argument.resource_or_id.failed_to_parse", error, report=True) from None
        problem = pack_conditions.problem(value, version)
        if problem:
            raise CommandFailure("argument.resource_or_id.failed_to_parse", problem[0], report=True)
    else:
        value = state.resources.predicates.get(predicate)
        if value is None:
            if version >= (1, 20, 5):
                raise CommandFailure("argument.resource_or_id.no_such_element", predicate, "minecraft:predicate",
                                     report=True)
            raise CommandFailure("predicate.unknown", predicate, report=True)
    loot = LootContext(state, ctx.pos, this=executor(state, ctx), dimension=ctx.dimension)
    if predicate[:1] not in "{[":
        loot.visit("predicate " + predicate)  # ConditionReference: a predicate reaching itself is false
    return predicates.test(value, loot)


def passes(env, cond: ast.Condition, ctx) -> bool:
    return (count(env, cond, ctx) > 0) != cond.negated


def as_command(env, cond: ast.Condition, ctx) -> int:
    """The test as the final command: its result, or a failure."""
    found = count(env, cond, ctx)
    if not cond.negated:
        if found > 0:
            return found
        raise CommandFailure("commands.execute.conditional.fail")
    if found == 0:
        return 1
    if isinstance(cond, _COUNTING):
        raise CommandFailure("commands.execute.conditional.fail_count", found)
    raise CommandFailure("commands.execute.conditional.fail")


def _score_matches(env, cond: ast.IfScoreMatches, ctx) -> bool:
    """ExecuteCommand.checkScore (range): the holder, then the objective; an unset score never matches."""
    holder = single_holder(env, cond.target, ctx)
    value = env.state.scoreboard.get(holder, objective(env, cond.objective))
    return value is not None and cond.range.contains(value)


def _score_compare(env, cond: ast.IfScore, ctx) -> bool:
    """ExecuteCommand.checkScore: target, its objective, source, its objective (in that order);
    false when either score is unset."""
    target = single_holder(env, cond.target, ctx)
    obj = objective(env, cond.objective)
    source = single_holder(env, cond.source, ctx)
    src_obj = objective(env, cond.source_objective)
    a = env.state.scoreboard.get(target, obj)
    b = env.state.scoreboard.get(source, src_obj)
    return a is not None and b is not None and _COMPARE[cond.op](a, b)
