"""``execute`` stages that change or filter the sources (the redirect and fork modifiers).

:func:`apply` maps one source to the sources the stage produces (ExecuteCommand.register).
Positions follow the game's argument rules where they cannot be wrong without entities:
``~`` is relative to the source position, absolute integer x/z are block centres, ``align``
floors, ``in`` scales x/z by the dimensions' coordinate scale. Local coordinates (``^``) and
``facing`` use plain double trigonometry here, not the game's float tables.
"""
from __future__ import annotations

import math

from mcfunction_parser import ast

from . import conditions, data
from .failure import CommandFailure, unsupported
from .holders import holder_names, select_entities
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
    if isinstance(sub, ast.StoreData):
        return [data.store_data(env, sub, source)]
    if isinstance(sub, (ast.ExAs, ast.ExAt, ast.ExPositionedAs, ast.ExRotatedAs, ast.ExFacingEntity)):
        # each entity found gives a source; none are modelled yet (see holders.select_entities)
        return [source for _ in select_entities(sub.targets, source)]
    if isinstance(sub, ast.ExOn):
        return []  # the server has no relations; entities are not modelled
    if isinstance(sub, ast.ExPositioned):
        return [source.with_context(pos=position(sub.pos, source), anchor="feet")]
    if isinstance(sub, ast.ExRotated):
        return [source.with_context(rot=rotation(sub.rot, source))]
    if isinstance(sub, ast.ExFacing):
        return [source.with_context(rot=facing(source.context.pos, position(sub.pos, source)))]
    if isinstance(sub, ast.ExAnchored):
        return [source.with_context(anchor=sub.anchor)]
    if isinstance(sub, ast.ExAlign):
        pos = tuple(float(math.floor(v)) if axis in sub.axes else v for axis, v in zip("xyz", source.context.pos))
        return [source.with_context(pos=pos)]
    if isinstance(sub, ast.ExIn):
        return [in_dimension(source, sub.dimension)]
    raise unsupported(f"'execute {type(sub).__name__.removeprefix('Ex').lower()}'")


def store_score(env, sub: ast.StoreScore, source: Source) -> Source:
    """``store result|success score``: holders and objective are resolved now; the callback
    stores into each (get-or-create) whenever the command reports a result, 0 on failure."""
    board = env.state.scoreboard
    names = holder_names(sub.targets, source, board)
    obj = objective(env, sub.objective)
    want_result = sub.kind == "result"

    def store(success: bool, value: int) -> None:
        stored = value if want_result else int(success)
        for name in names:
            board.set(name, obj, stored)

    return source.with_callback(chain(source.callback, store))


def position(vec: ast.Vec3, source: Source) -> tuple[float, float, float]:
    """Vec3Argument: world coordinates (absolute integer x/z centred) or local ``^`` coordinates."""
    if vec.is_local:
        return _local(vec, source)
    base = source.context.pos
    out = []
    for axis, coord, origin in zip("xyz", (vec.x, vec.y, vec.z), base):
        if coord.kind == "rel":
            out.append(origin + coord.value)
        elif coord.is_int and axis != "y":
            out.append(coord.value + 0.5)
        else:
            out.append(float(coord.value))
    return tuple(out)


def rotation(vec: ast.Vec2, source: Source) -> tuple[float, float]:
    yaw, pitch = source.context.rot
    new_yaw = yaw + vec.x.value if vec.x.kind == "rel" else vec.x.value
    new_pitch = pitch + vec.y.value if vec.y.kind == "rel" else vec.y.value
    return (new_yaw, new_pitch)


def facing(origin, target) -> tuple[float, float]:
    dx, dy, dz = (t - o for t, o in zip(target, origin))
    horizontal = math.sqrt(dx * dx + dz * dz)
    pitch = -math.degrees(math.atan2(dy, horizontal))
    yaw = math.degrees(math.atan2(dz, dx)) - 90.0
    return (_wrap_degrees(yaw), _wrap_degrees(pitch))


def in_dimension(source: Source, dimension: str) -> Source:
    """CommandSourceStack.withLevel: x and z scale by the ratio of coordinate scales."""
    if dimension == source.context.dimension:
        return source
    scale = _COORDINATE_SCALE.get(source.context.dimension, 1.0) / _COORDINATE_SCALE.get(dimension, 1.0)
    x, y, z = source.context.pos
    return source.with_context(dimension=dimension, pos=(x * scale, y, z * scale))


def _local(vec: ast.Vec3, source: Source) -> tuple[float, float, float]:
    yaw, pitch = source.context.rot
    left, up, forwards = vec.x.value, vec.y.value, vec.z.value
    cy, sy = math.cos(math.radians(yaw + 90.0)), math.sin(math.radians(yaw + 90.0))
    cp, sp = math.cos(math.radians(-pitch)), math.sin(math.radians(-pitch))
    cp2, sp2 = math.cos(math.radians(-pitch + 90.0)), math.sin(math.radians(-pitch + 90.0))
    f = (cy * cp, sp, sy * cp)
    u = (cy * cp2, sp2, sy * cp2)
    l_ = (f[1] * u[2] - f[2] * u[1], f[2] * u[0] - f[0] * u[2], f[0] * u[1] - f[1] * u[0])
    l_ = (-l_[0], -l_[1], -l_[2])
    x, y, z = source.context.pos
    return (
        x + f[0] * forwards + u[0] * up + l_[0] * left,
        y + f[1] * forwards + u[1] * up + l_[1] * left,
        z + f[2] * forwards + u[2] * up + l_[2] * left,
    )


def _wrap_degrees(angle: float) -> float:
    angle = math.fmod(angle, 360.0)
    if angle >= 180.0:
        angle -= 360.0
    if angle < -180.0:
        angle += 360.0
    return angle


def fork_limit_reached(limit: int) -> CommandFailure:
    """BuildContexts.ERROR_FORK_LIMIT_REACHED: a stage would produce ``limit`` sources or more."""
    return CommandFailure(f"Maximum number of contexts ({limit}) reached", report=True)
