"""The execute stages that change or filter the context (ExecuteCommand.register, decompiled 1.21):
``as at positioned [as] rotated [as] facing [entity] anchored align in on summon`` and the
conditions. :func:`stage` maps one context to the contexts the stage makes (none, one, or one per
entity, in the game's order); whether a failure stops the whole command or only this context
(``fork``) is the backend's control flow. ``store`` stages are :mod:`.stores`.

Positions and rotations use the world library's game math (:mod:`emulator.world.source`), with
the executor for the eye anchor; ``in`` scales x/z by the dimensions' coordinate scale
(CommandSourceStack.withLevel) and fails for a dimension the server does not have; ``at`` takes
the entity's level, ``positioned as`` does not.
"""
from __future__ import annotations

from dataclasses import replace

from emulator.world import projectiles, relations
from emulator.world.context import Context
from mcfunction_parser import ast

from . import conditions, entities
from .entities import context_as, executor, world_source

def stage(env, st: ast.Subcommand, ctx: Context) -> list[Context]:
    """The contexts ``st`` makes from ``ctx``."""
    if isinstance(st, ast.Condition):
        return [ctx] if conditions.passes(env, st, ctx) else []
    made = _BY_ENTITY.get(type(st))
    if made is not None:
        return made(env, st, ctx)
    modify = _MODIFIERS.get(type(st))
    if modify is not None:
        return [modify(env, st, ctx)]
    # positioned over ...: the world has no terrain; going on unchanged keeps the scores the
    # rest of the chain computes
    env.warn(st, f"'{type(st).__name__}' is not emulated: the context is kept unchanged")
    return [ctx]


# ---------------------------------------------------------------------- entity stages
def _entity_contexts(env, st, ctx: Context) -> list[Context]:
    """``as``, ``at``, ``positioned as``, ``rotated as``: a context per entity found."""
    kind = entities.ENTITY_CONTEXT_STAGES.index(type(st))
    return [entities.entity_stage_context(kind, env.state, ctx, e) for e in entities.select(env.state, st.targets, ctx)]


def _facing_entity(env, st: ast.ExFacingEntity, ctx: Context) -> list[Context]:
    source = world_source(env.state, ctx)
    return [_rotated(ctx, source.facing_entity(e, st.anchor)) for e in entities.select(env.state, st.targets, ctx)]


def _on(env, st: ast.ExOn, ctx: Context) -> list[Context]:
    """``on RELATION``: only the executor changes; no executor, or nothing related, gives no context."""
    related = relations.related(env.state, executor(env.state, ctx), st.relation)
    return [context_as(env.state, ctx, e) for e in related]


def _summon(env, st: ast.ExSummon, ctx: Context) -> list[Context]:
    made = env.state.entities.summon(st.entity_type, ctx.pos, dimension=ctx.dimension)
    projectiles.launched(env.state, made)
    return [context_as(env.state, ctx, made)]


_BY_ENTITY = {
    **{kind: _entity_contexts for kind in entities.ENTITY_CONTEXT_STAGES},
    ast.ExFacingEntity: _facing_entity,
    ast.ExOn: _on,
    ast.ExSummon: _summon,
}


# ---------------------------------------------------------------------- position and rotation
def _rotated(ctx: Context, source) -> Context:
    return replace(ctx, rot=(float(source.yaw), float(source.pitch)))


def _positioned(env, st: ast.ExPositioned, ctx: Context) -> Context:
    """``positioned X Y Z``: the anchor goes back to the feet."""
    return replace(ctx, pos=world_source(env.state, ctx).position_of(st.pos), anchor="feet")


def _rotated_by(env, st: ast.ExRotated, ctx: Context) -> Context:
    yaw, pitch = world_source(env.state, ctx).rotation_of(st.rot)
    return replace(ctx, rot=(float(yaw), float(pitch)))


def _facing(env, st: ast.ExFacing, ctx: Context) -> Context:
    source = world_source(env.state, ctx)
    return _rotated(ctx, source.facing_position(source.position_of(st.pos)))


def _anchored(env, st: ast.ExAnchored, ctx: Context) -> Context:
    return replace(ctx, anchor=st.anchor)


def _aligned(env, st: ast.ExAlign, ctx: Context) -> Context:
    return replace(ctx, pos=world_source(env.state, ctx).aligned(st.axes).pos)


def _in_dimension(env, st: ast.ExIn, ctx: Context) -> Context:
    """CommandSourceStack.withLevel: x and z scale by the ratio of coordinate scales."""
    scale = env.state.entities.table.levels.teleportation_scale(ctx.dimension, st.dimension)
    if st.dimension == ctx.dimension:
        return ctx
    x, y, z = ctx.pos
    return replace(ctx, dimension=st.dimension, pos=(x * scale, y, z * scale))


_MODIFIERS = {
    ast.ExPositioned: _positioned,
    ast.ExRotated: _rotated_by,
    ast.ExFacing: _facing,
    ast.ExAnchored: _anchored,
    ast.ExAlign: _aligned,
    ast.ExIn: _in_dimension,
}
