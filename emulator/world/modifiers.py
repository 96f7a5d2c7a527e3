"""The ``execute`` stages that only move, turn, anchor or re-dimension the context (ExecuteCommand's
redirect modifiers ``positioned X Y Z``, ``rotated``, ``facing X Y Z``, ``anchored``, ``align``,
``in``), on a :class:`~emulator.world.state.Context` and the entity executing it.

``^`` and ``facing`` start from the anchor position: anchored at the eyes, the executing entity's
(EntityAnchorArgument.Anchor.EYES: ``pos + (0, entity.getEyeHeight(), 0)``; without an entity the
position as is). ``in`` scales x and z by the ratio of the two dimensions' coordinate scales
(CommandSourceStack.withLevel, DimensionType.getTeleportationScale).
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from emulator.world.source import Source
from emulator.world.state import Context
from mcfunction_parser import ast

MODIFIERS = (ast.ExPositioned, ast.ExRotated, ast.ExFacing, ast.ExAnchored, ast.ExAlign, ast.ExIn)
COORDINATE_SCALE = {"minecraft:the_nether": 8.0}  # DimensionType.coordinateScale; the others' is 1

_SOURCE_MODIFIERS = {
    ast.ExPositioned: lambda src, st: src.positioned(st.pos),  # also resets the anchor to the feet
    ast.ExRotated: lambda src, st: src.with_rotation(*src.rotation_of(st.rot)),
    ast.ExFacing: lambda src, st: src.facing_position(src.position_of(st.pos)),
    ast.ExAnchored: lambda src, st: src.with_anchor(st.anchor),
    ast.ExAlign: lambda src, st: src.aligned(st.axes),
}


def modified(st: ast.Subcommand, ctx: Context, entity) -> Context:
    """The context stage ``st`` (one of :data:`MODIFIERS`) makes of ``ctx``, run by ``entity``
    (an :class:`~emulator.world.entities.Entity`, None for the server)."""
    if isinstance(st, ast.ExIn):
        return in_dimension(ctx, st.dimension)
    source = Source(pos=ctx.pos, yaw=np.float32(ctx.rot[0]), pitch=np.float32(ctx.rot[1]), entity=entity,
                    anchor=ctx.anchor)
    moved = _SOURCE_MODIFIERS[type(st)](source, st)
    return replace(ctx, pos=tuple(moved.pos), rot=(float(moved.yaw), float(moved.pitch)), anchor=moved.anchor)


def in_dimension(ctx: Context, dimension: str) -> Context:
    if dimension == ctx.dimension:
        return ctx
    scale = COORDINATE_SCALE.get(ctx.dimension, 1.0) / COORDINATE_SCALE.get(dimension, 1.0)
    x, y, z = ctx.pos
    return replace(ctx, dimension=dimension, pos=(x * scale, y, z * scale))
