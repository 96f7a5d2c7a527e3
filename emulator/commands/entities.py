"""Entity, block and NBT-data commands on a :class:`~emulator.world.state.WorldState`: the one place both
backends (the reference interpreter and the numba VM's host side) run them, so they agree.

Everything here takes the world state and an execution :class:`~emulator.world.state.Context` and calls
the world library (:mod:`emulator.world`). A context names its executor by an integer id: the
entity's creation index (``Entity.order``), registered in ``state.executors`` when a context is
made for it, so ``@s`` keeps reaching an entity even after it was killed (as the game's source
keeps its entity object).

- ``select(state, target, ctx)``: the entities a selector / name / UUID finds (maybe none).
- ``holder_names(state, selector, ctx)``: score holders named by a selector (none fails).
- ``stage(state, sub, ctx)``: the contexts an entity stage (``as at positioned as rotated as facing
  entity on summon``) makes from one context.
- ``condition_count(state, cond, ctx)``: ``if entity|data|block|blocks``: what the test counts.
- ``command(state, cmd, ctx, warn)``: ``summon kill tag tp data setblock fill``; the int result.
- ``store_target(state, sub, ctx)`` then ``store(state, target, sub, success, value)``: ``execute
  store ... entity|block`` (the target is resolved when the stage runs, as the game's modifier does).
- ``new_state(shuffle)``, ``parse_target(text)``, ``describe(state, entity)``: the API's side.

The numba VM keeps entities as arrays (:mod:`emulator.vm.entity_arrays`): it reloads them after any
host op that may change entities, so nothing here needs to notify it.

Failures raise :class:`WorldCommandError` (``report``: also worth a diagnostic, e.g. an
unsupported selector argument); backends turn it into their failed command.
"""
from __future__ import annotations

import random
from contextlib import contextmanager
from dataclasses import replace

import numpy as np

from emulator.world.state import SERVER, Context, WorldState
from emulator.world import commands as world_commands
from emulator.world import data_commands, relations, stores
from emulator.world.blocks import block_pos, parse_block
from emulator.world.data_commands import World
from emulator.world.entities import ENTITY_TYPES, POS_LIMIT_XZ, POS_LIMIT_Y, Entity, EntityStore
from emulator.world.errors import CommandFailure as WorldFailure
from emulator.world.selectors import SelectorQuery, UnsupportedSelector
from emulator.world.source import Source
from emulator.world.storage import CommandStorage
from mcfunction_parser import ast, selectors
from mcfunction_parser.arguments import holder_from_word, vec3
from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.reader import ParseError, Reader

ENTITY_STAGES = (ast.ExAs, ast.ExAt, ast.ExPositionedAs, ast.ExRotatedAs, ast.ExFacingEntity, ast.ExOn,
                 ast.ExSummon)
ENTITY_COMMANDS = (ast.Summon, ast.Kill, ast.TagCommand, ast.Teleport)
BLOCK_COMMANDS = ("setblock", "fill")


class WorldCommandError(Exception):
    """A failed command; ``report``: the failure points at a limit of the emulator or a pack bug."""

    def __init__(self, message: str, report: bool = False) -> None:
        super().__init__(message)
        self.message = message
        self.report = report


class ShuffledEntityStore(EntityStore):
    """``--shuffle SEED``: each new entity goes to a random place in the iteration order, so unsorted
    ``@e`` visits entities in a seeded permutation instead of creation order (order-dependent packs
    show up as different results)."""

    def __init__(self, seed: int = 0, shuffle_seed: int = 0) -> None:
        super().__init__(seed)
        self.shuffle_rng = random.Random(shuffle_seed)

    def _add(self, entity: Entity) -> Entity:
        super()._add(entity)
        self.entities.insert(self.shuffle_rng.randint(0, len(self.entities) - 1), self.entities.pop())
        return entity


@contextmanager
def failures():
    """The world library's failures are this command's failures, with the game's message."""
    try:
        yield
    except WorldFailure as failure:
        raise WorldCommandError(failure.message) from None
    except UnsupportedSelector as unsupported:
        raise WorldCommandError(f"selector argument '{unsupported}' is not supported", report=True) from None


# ---------------------------------------------------------------------- contexts
def executor(state: WorldState, ctx: Context) -> Entity | None:
    return None if ctx.executor == SERVER else state.executors.get(ctx.executor)


def register(state: WorldState, entity: Entity) -> int:
    """The executor id of ``entity`` (its creation index), registered for later lookups."""
    state.executors[entity.order] = entity
    return entity.order


def world_source(state: WorldState, ctx: Context) -> Source:
    return Source(pos=ctx.pos, yaw=np.float32(ctx.rot[0]), pitch=np.float32(ctx.rot[1]), entity=executor(state, ctx), anchor=ctx.anchor)


def context_as(state: WorldState, ctx: Context, entity: Entity) -> Context:
    return replace(ctx, executor=register(state, entity))


def context_at(ctx: Context, entity: Entity) -> Context:
    """``execute at``: the entity's position and rotation (the executor stays)."""
    return replace(ctx, pos=entity.pos, rot=(float(entity.yaw), float(entity.pitch)))


# The stages that make one context per entity from the entity alone, by the VM's kind number
# (OP_ASSTAGE's operand): as, at, positioned as, rotated as
ENTITY_CONTEXT_STAGES = (ast.ExAs, ast.ExAt, ast.ExPositionedAs, ast.ExRotatedAs)


def entity_stage_context(kind: int, state: WorldState, ctx: Context, entity: Entity) -> Context:
    """The context stage ``ENTITY_CONTEXT_STAGES[kind]`` makes from ``ctx`` for ``entity``."""
    if kind == 0:
        return context_as(state, ctx, entity)
    if kind == 1:
        return context_at(ctx, entity)
    if kind == 2:
        return replace(ctx, pos=entity.pos)
    return replace(ctx, rot=(float(entity.yaw), float(entity.pitch)))


def _with_source(ctx: Context, source: Source) -> Context:
    return replace(ctx, pos=tuple(source.pos), rot=(float(source.yaw), float(source.pitch)))


def entity_context(state: WorldState, entity: Entity, anchor: str = "feet") -> Context:
    """A context run by ``entity`` at its position and rotation (``Emulator.call(as_=...)``)."""
    return Context(register(state, entity), entity.pos, (float(entity.yaw), float(entity.pitch)), anchor)


# ---------------------------------------------------------------------- selectors
def _scores(state: WorldState):
    return state.scoreboard.get


def _options(state: WorldState) -> dict:
    return {"scores": _scores(state)}


def _query(state: WorldState, selector: ast.Selector) -> SelectorQuery:
    """A selector's tests are built once per AST node (nodes are immutable and live for the run)."""
    query = state.selector_cache.get(id(selector))
    if query is None or query[0] is not selector:
        with failures():
            query = state.selector_cache[id(selector)] = (selector, SelectorQuery(selector))
    return query[1]


def select(state: WorldState, target, ctx: Context) -> list[Entity]:
    """EntityArgument.getOptionalEntities: what a selector, player name or UUID finds."""
    with failures():
        if isinstance(target, ast.Selector):
            return _query(state, target).run(state.entities, world_source(state, ctx), _scores(state))
        try:
            return world_commands.resolve_entities(target, state.entities, world_source(state, ctx))
        except WorldFailure:
            return []  # a name or UUID that finds no entity


def _found(state: WorldState, target, ctx: Context) -> list[Entity]:
    found = select(state, target, ctx)
    if not found:
        raise WorldCommandError("No entity was found")
    return found


def _single(state: WorldState, target, ctx: Context) -> Entity:
    found = _found(state, target, ctx)
    if len(found) > 1:
        raise WorldCommandError("Only one entity is allowed, but the provided selector allows more than one")
    return found[0]


def holder_names(state: WorldState, selector: ast.Selector, ctx: Context) -> list[str]:
    """ScoreHolderArgument with a selector: each entity's holder name (UUID, or player name)."""
    return [e.score_holder for e in _found(state, selector, ctx)]


# ---------------------------------------------------------------------- execute stages
def stage(state: WorldState, sub: ast.Subcommand, ctx: Context) -> list[Context]:
    """The contexts an entity stage makes from ``ctx``, in the game's order (ExecuteCommand)."""
    if isinstance(sub, ast.ExSummon):
        with failures():
            entity = state.entities.summon(sub.entity_type, ctx.pos)
        return [context_as(state, ctx, entity)]
    if isinstance(sub, ast.ExOn):
        return [context_as(state, ctx, e) for e in relations.related(state.entities, executor(state, ctx), sub.relation)]
    entities = select(state, sub.targets, ctx)
    if isinstance(sub, ENTITY_CONTEXT_STAGES):
        kind = ENTITY_CONTEXT_STAGES.index(type(sub))
        return [entity_stage_context(kind, state, ctx, e) for e in entities]
    source = world_source(state, ctx)
    return [_with_source(ctx, source.facing_entity(e, sub.anchor)) for e in entities]


def is_world_stage(sub: ast.Subcommand) -> bool:
    return isinstance(sub, ENTITY_STAGES)


# ---------------------------------------------------------------------- conditions
def is_world_condition(cond: ast.Subcommand) -> bool:
    return isinstance(cond, (ast.IfEntity, ast.IfBlock, ast.IfBlocks)) or (
        isinstance(cond, ast.IfData) and not isinstance(cond.source, ast.StorageData))


def condition_count(state: WorldState, cond: ast.Condition, ctx: Context) -> int:
    """``if entity`` (the count), ``if data entity|block`` (the matches), ``if block`` (0/1),
    ``if blocks`` (the matching block count, or 0)."""
    if isinstance(cond, ast.IfEntity):
        return len(select(state, cond.targets, ctx))
    source = world_source(state, ctx)
    with failures():
        if isinstance(cond, ast.IfData):
            return data_commands.if_data(_accessor(state, cond.source, ctx), cond.path)
        if isinstance(cond, ast.IfBlock):
            return int(state.blocks.test(block_pos(source, cond.pos), _block(cond.block)))
        found = state.blocks.compare_regions(block_pos(source, cond.start), block_pos(source, cond.end),
                                             block_pos(source, cond.destination), cond.mode == "masked")
        return found or 0


def _block(text: str):
    try:
        return parse_block(text)
    except ValueError as error:
        raise WorldCommandError(f"invalid block '{text}': {error}", report=True) from None


# ---------------------------------------------------------------------- data
def _world(state: WorldState, ctx: Context) -> World:
    return World(state.entities, state.blocks, CommandStorage(state.storage), world_source(state, ctx),
                 _options(state))


def _accessor(state: WorldState, target: ast.DataTarget, ctx: Context):
    if isinstance(target, ast.EntityData):  # resolved here so a missing entity fails with our message
        return data_commands.EntityAccessor(_single(state, target.target, ctx))
    return data_commands.accessor(target, _world(state, ctx))


def is_world_data(cmd: ast.Command) -> bool:
    """A ``data`` command reaching an entity or a block (as target or as ``from`` source)."""
    targets = [getattr(cmd, "target", None), getattr(getattr(cmd, "source", None), "source", None)]
    return isinstance(cmd, (ast.DataGet, ast.DataMerge, ast.DataModify, ast.DataRemove)) and any(
        isinstance(t, (ast.EntityData, ast.BlockData)) for t in targets)


def _data(state: WorldState, cmd, ctx: Context) -> int:
    if isinstance(cmd, ast.DataModify):
        values = _modify_values(state, cmd.source, ctx)
        return data_commands.data_modify(_accessor(state, cmd.target, ctx), cmd.path, cmd.mode, cmd.index, values)
    acc = _accessor(state, cmd.target, ctx)
    if isinstance(cmd, ast.DataGet):
        return data_commands.data_get(acc, cmd.path, cmd.scale)
    if isinstance(cmd, ast.DataMerge):
        return data_commands.data_merge(acc, cmd.nbt)
    return data_commands.data_remove(acc, cmd.path)


def _modify_values(state: WorldState, source, ctx: Context) -> list:
    if isinstance(source, ast.SourceValue):
        return [source.value]
    acc = _accessor(state, source.source, ctx)
    if isinstance(source, ast.SourceString):
        return data_commands.string_values(acc, source.path, source.start, source.end)
    return data_commands.source_values(acc, source.path)


def is_world_store(sub: ast.Subcommand) -> bool:
    return isinstance(sub, ast.StoreData) and not isinstance(sub.target, ast.StorageData)


def store_target(state: WorldState, sub: ast.StoreData, ctx: Context):
    """The ``store`` stage: its entity (one, or the command fails) or block, resolved now."""
    with failures():
        return _accessor(state, sub.target, ctx)


def store(state: WorldState, target, sub: ast.StoreData, success: bool, value: int) -> None:
    """The store callback: ``result`` stores the value (0 on failure), ``success`` 1/0; every
    failure is silent (ExecuteCommand.storeData)."""
    stored = (value if success else 0) if sub.kind == "result" else int(success)
    axis = _position_axis(target, sub)
    if axis is not None:
        _store_position(target.entity, axis, float(stores.stored_tag("double", stored, sub.scale)))
        return
    data_commands.store_data(target, sub.path, sub.type, stored, sub.scale)


def _position_axis(target, sub: ast.StoreData) -> int | None:
    """The axis of ``store ... entity E Pos[0|1|2] double S`` on a non-player, else None."""
    nodes = sub.path.nodes
    if (sub.type == "double" and isinstance(target, data_commands.EntityAccessor) and not target.entity.is_player
            and len(nodes) == 2 and nodes[0] == ast.PathKey("Pos") and isinstance(nodes[1], ast.PathIndex)
            and nodes[1].index in (0, 1, 2)):
        return nodes[1].index
    return None


def _store_position(entity: Entity, axis: int, value: float) -> None:
    """What the entity accessor's save, ``set Pos[axis]``, load does to the entity: the position
    component, clamped as ``Entity.load`` clamps it (every other saved field reads back unchanged;
    tests/backends/test_entities.py checks this shortcut against the full round trip)."""
    limit = POS_LIMIT_Y if axis == 1 else POS_LIMIT_XZ
    pos = list(entity.pos)
    pos[axis] = max(-limit, min(value, limit))
    entity.pos = tuple(pos)


# ---------------------------------------------------------------------- final commands
def is_world_command(cmd: ast.Command) -> bool:
    return isinstance(cmd, ENTITY_COMMANDS) or is_world_data(cmd) or (
        isinstance(cmd, ast.GenericCommand) and cmd.name in BLOCK_COMMANDS)


def command(state: WorldState, cmd: ast.Command, ctx: Context, warn) -> int:
    """Run one world command for ``ctx``; ``warn(node, message)`` reports a warning once."""
    source = world_source(state, ctx)
    with failures():
        if isinstance(cmd, ast.Summon):
            if cmd.entity_type not in ENTITY_TYPES:
                warn(cmd, f"unknown entity type '{cmd.entity_type}': summoned with the default size 0.6 x 1.8")
            world_commands.summon_command(cmd, state.entities, source)
            return 1
        if isinstance(cmd, ast.Kill):
            return _kill(state, cmd, source)
        if isinstance(cmd, ast.TagCommand):
            return world_commands.tag_command(cmd, state.entities, source, **_options(state))
        if isinstance(cmd, ast.Teleport):
            return world_commands.teleport_command(cmd, state.entities, source, **_options(state))
        if isinstance(cmd, ast.GenericCommand):
            return _block_command(state, cmd, source)
        return _data(state, cmd, ctx)


def _kill(state: WorldState, cmd: ast.Kill, source: Source) -> int:
    """``kill``; a removed entity loses every score (Scoreboard.entityRemoved -> resetAllPlayerScores)."""
    before = list(state.entities.entities)
    count = world_commands.kill_command(cmd, state.entities, source, **_options(state))
    for entity in before:
        if not entity.alive:
            state.scoreboard.reset(entity.score_holder)
    return count


def _block_command(state: WorldState, cmd: ast.GenericCommand, source: Source) -> int:
    """``setblock POS BLOCK [MODE]`` / ``fill FROM TO BLOCK [MODE]`` (``replace FILTER`` too)."""
    reader = Reader(cmd.text, cmd.loc, (1, 21, 0))
    try:
        reader.pos = len(cmd.name) + 1
        corners = [vec3(reader, block=True)]
        if cmd.name == "fill":
            reader.pos += 1
            corners.append(vec3(reader, block=True))
    except ParseError as error:
        raise WorldCommandError(f"'{cmd.name}': {error}", report=True) from None
    words = cmd.text[reader.pos:].split()
    if not words:
        raise WorldCommandError(f"'{cmd.name}': expected a block", report=True)
    spec, mode = _block(words[0]), (words[1] if len(words) > 1 else "replace")
    positions = [block_pos(source, corner) for corner in corners]
    if cmd.name == "setblock":
        return state.blocks.setblock(positions[0], spec, mode)
    block_filter = None
    if mode == "replace" and len(words) > 2:
        kept = _block(words[2])
        block_filter = lambda pos: state.blocks.test(pos, kept)  # noqa: E731 - FillCommand's filter
    return state.blocks.fill(positions[0], positions[1], spec, mode, block_filter)


# ---------------------------------------------------------------------- the API's view
def new_state(shuffle: int | None = None) -> WorldState:
    """A fresh world; with ``shuffle``, unsorted ``@e`` visits entities in a seeded permutation."""
    state = WorldState()
    if shuffle is not None:
        state.entities = ShuffledEntityStore(shuffle_seed=shuffle)
    return state


def parse_target(text: str):
    """A selector, player name or UUID written as in a command (ValueError when malformed)."""
    reader = Reader(text, Loc("<selector>", 1, 1), (1, 21, 0))
    try:
        target = selectors.selector(reader) if text.startswith("@") else holder_from_word(text, reader.loc())
    except ParseError as error:
        raise ValueError(f"bad selector {text!r}: {error.message}") from None
    if isinstance(target, ast.Selector) and reader.pos != len(text):
        raise ValueError(f"bad selector {text!r}: unexpected text {text[reader.pos:]!r}")
    return target


def describe(state: WorldState, entity: Entity) -> dict:
    """What ``Emulator.entities`` and ``dpemu run --json`` show of an entity."""
    holder = entity.score_holder
    scores = {obj: value for obj, holders in state.scoreboard.scores().items()
              if (value := holders.get(holder)) is not None}
    return {"uuid": entity.uuid_string, "type": entity.type, "name": entity.player_name,
            "tags": sorted(entity.tags), "pos": list(entity.pos),
            "rotation": [float(entity.yaw), float(entity.pitch)], "scores": scores}
