"""``execute`` stages that change or filter the sources (the redirect and fork modifiers).

:func:`apply` maps one source to the sources the stage produces (ExecuteCommand.register).
Positions and rotations use the world library's game math (:mod:`emulator.world.source`);
``in`` scales x/z by the dimensions' coordinate scale (CommandSourceStack.withLevel).
"""
from __future__ import annotations

from emulator.world import bossbars
from emulator.world.source import Source as WorldSource
from mcfunction_parser import ast

from . import conditions, data, entities
from .failure import CommandFailure
from .holders import holder_names
from .queue import chain
from .scoreboard import objective
from .source import Source

# DimensionType.coordinateScale of the vanilla dimensions
_COORDINATE_SCALE = {"minecraft:the_nether": 8.0}

# Stages built with ``fork`` in ExecuteCommand.register (errors in one context don't stop others)
FORKS = (ast.ExAs, ast.ExAt, ast.ExPositionedAs, ast.ExRotatedAs, ast.ExFacingEntity, ast.ExOn, ast.Condition)


def apply(env, sub: ast.Subcommand, source: Source) -> list[Source]:
    if isinstance(sub, ast.Condition):
        return [source] if conditions.passes(env, sub, source) else []
    if isinstance(sub, ast.StoreScore):
        return [store_score(env, sub, source)]
    if isinstance(sub, ast.StoreData) and isinstance(sub.target, ast.StorageData):
        return [data.store_data(env, sub, source)]
    if isinstance(sub, ast.StoreData):  # into an entity or a block
        return [entities.store_data(sub, source)]
    if isinstance(sub, ast.StoreBossbar):
        return [store_bossbar(sub, source)]
    if isinstance(sub, entities.world.ENTITY_STAGES):
        return entities.stage(sub, source)
    if isinstance(sub, ast.ExPositioned):
        return [source.with_context(pos=_world(source).position_of(sub.pos), anchor="feet")]
    if isinstance(sub, ast.ExRotated):
        return [_with_rotation(source, _world(source).rotation_of(sub.rot))]
    if isinstance(sub, ast.ExFacing):
        world = _world(source)
        turned = world.facing_position(world.position_of(sub.pos))
        return [_with_rotation(source, (turned.yaw, turned.pitch))]
    if isinstance(sub, ast.ExAnchored):
        return [source.with_context(anchor=sub.anchor)]
    if isinstance(sub, ast.ExAlign):
        return [source.with_context(pos=_world(source).aligned(sub.axes).pos)]
    if isinstance(sub, ast.ExIn):
        return [in_dimension(source, sub.dimension)]
    # positioned over: the world has no terrain; going on unchanged keeps the scores
    # the rest of the chain computes
    env.warn_once(sub, f"'{type(sub).__name__}' is not emulated: the context is kept unchanged", source)
    return [source]


def store_bossbar(sub: ast.StoreBossbar, source: Source) -> Source:
    """``store result|success bossbar ID value|max``: the bar is looked up now (an unknown one
    fails the stage); the callback writes the result into it."""
    with data.world_failures():
        bar = bossbars.store_target(source.state.bossbars, sub)

    def store(success: bool, value: int) -> None:
        bossbars.store(bar, sub, success, value)

    return source.with_callback(chain(source.callback, store))


def store_score(env, sub: ast.StoreScore, source: Source) -> Source:
    """``store result|success score``: holders and objective are resolved now; the callback
    stores into each (get-or-create) whenever the command reports a result, 0 on failure."""
    board = env.state.scoreboard
    names = holder_names(sub.targets, source, board)
    obj = objective(env, sub.objective)
    want_result = sub.kind == "result"

    def store(success: bool, value: int) -> None:
        if not board.exists(obj):
            return  # removed meanwhile: the game writes to the dropped Objective, which nothing sees
        stored = value if want_result else int(success)
        for name in names:
            board.set(name, obj, stored)

    return source.with_callback(chain(source.callback, store))


def _world(source: Source) -> WorldSource:
    """The world library's view of the source (with its executing entity, for the eye anchor)."""
    return entities.world.world_source(source.state, source.context)


def _with_rotation(source: Source, rot) -> Source:
    return source.with_context(rot=(float(rot[0]), float(rot[1])))


def in_dimension(source: Source, dimension: str) -> Source:
    """CommandSourceStack.withLevel: x and z scale by the ratio of coordinate scales."""
    if dimension == source.context.dimension:
        return source
    scale = _COORDINATE_SCALE.get(source.context.dimension, 1.0) / _COORDINATE_SCALE.get(dimension, 1.0)
    x, y, z = source.context.pos
    return source.with_context(dimension=dimension, pos=(x * scale, y, z * scale))


def fork_limit_reached(limit: int) -> CommandFailure:
    """BuildContexts.ERROR_FORK_LIMIT_REACHED: a stage would produce ``limit`` sources or more."""
    return CommandFailure(f"Maximum number of contexts ({limit}) reached", report=True)
