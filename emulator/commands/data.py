"""``data`` commands, ``execute if data``, the data targets of ``execute store`` and the arguments
of ``function ... with``, on any of the three data targets (storage, entity, block).

A ``DataAccessor`` is how the game reaches a target's NBT:
- storage: the live compound (a new empty one for an unknown id), stored back on success
  (:class:`~emulator.world.storage.CommandStorage`: an empty compound removes the id);
- entity: a fresh NBT view, loaded back into the entity (UUID kept; players refuse);
- block: the block entity's NBT with ``x y z id`` (a block without one fails "not a block entity").
The NBT work itself is the world library's (:mod:`emulator.world.nbt_ops`, :mod:`emulator.world.stores`).

Sources (decompiled 1.21): server/commands/data/DataCommands.java, EntityDataAccessor.java,
BlockDataAccessor.java, StorageDataAccessor.java, server/commands/ExecuteCommand.java (storeData,
checkMatchingData), server/commands/FunctionCommand.java (getArgumentTag).
"""
from __future__ import annotations

from abc import ABC, abstractmethod
from typing import Callable

from emulator.world import command_blocks, nbt_ops, stores
from emulator.world.entities import POS_LIMIT_XZ, POS_LIMIT_Y, Entity, EntityStore, entity_nbt
from emulator.world.storage import CommandStorage
from mcfunction_parser import ast
from mcfunction_parser.nbt import Compound

from . import entities
from .blocks import loaded_block_pos
from emulator.world.errors import CommandFailure


class DataAccessor(ABC):
    """How a command reaches one target's NBT."""

    @abstractmethod
    def read(self) -> Compound:
        """The root compound (live for storage, a fresh view for entities and blocks)."""

    @abstractmethod
    def change(self, edit: Callable[[Compound], int]) -> int:
        """Run ``edit(root)`` and keep the result as the target's data; returns what ``edit`` returns."""


class StorageAccessor(DataAccessor):
    def __init__(self, storage: CommandStorage, storage_id: str) -> None:
        self.storage, self.id = storage, storage_id

    def read(self) -> Compound:
        return self.storage.get(self.id)

    def change(self, edit):
        return self.storage.modify(self.id, edit)


class EntityAccessor(DataAccessor):
    def __init__(self, entity: Entity, store: EntityStore) -> None:
        self.entity, self.store = entity, store

    def read(self) -> Compound:
        return entity_nbt(self.entity)

    def change(self, edit):
        return self.store.modify(self.entity, edit)


class BlockAccessor(DataAccessor):
    def __init__(self, state, dimension: str, pos) -> None:
        self.state, self.dimension, self.pos = state, dimension, pos
        self.blocks = state.blocks_in(dimension)
        self.blocks.block_nbt(pos)  # fails now for a block without a block entity, as the game's accessor does

    def read(self) -> Compound:
        return self.blocks.block_nbt(self.pos)

    def change(self, edit):
        before = self.blocks.entity(self.pos)
        result = self.blocks.modify_block(self.pos, edit)
        command_blocks.after_edit(self.state, self.dimension, self.pos, before)  # the entity loads again
        return result


def accessor(env, target: ast.DataTarget, ctx) -> DataAccessor:
    """The accessor of ``storage ID``, ``entity TARGET`` (exactly one entity) or ``block POS``."""
    state = env.state
    if isinstance(target, ast.StorageData):
        return StorageAccessor(CommandStorage(state.storage), target.id)
    if isinstance(target, ast.EntityData):
        return EntityAccessor(entities.single(state, target.target, ctx), state.entities)
    return BlockAccessor(state, ctx.dimension, loaded_block_pos(state, ctx, target.pos))


# ---------------------------------------------------------------------- commands
def data_get(env, cmd: ast.DataGet, ctx) -> int:
    """1 for the whole compound, else the value (floored, sizes for non-numbers), scaled if asked."""
    root = accessor(env, cmd.target, ctx).read()
    if cmd.path is None:
        return 1
    if cmd.scale is None:
        return stores.data_get(root, cmd.path)
    return stores.data_get_scaled(root, cmd.path, cmd.scale)


def data_merge(env, cmd: ast.DataMerge, ctx) -> int:
    return accessor(env, cmd.target, ctx).change(lambda root: nbt_ops.data_merge(root, cmd.nbt))


def data_remove(env, cmd: ast.DataRemove, ctx) -> int:
    return accessor(env, cmd.target, ctx).change(lambda root: nbt_ops.data_remove(root, cmd.path))


def data_modify(env, cmd: ast.DataModify, ctx) -> int:
    """The source's values are read before the target is reached (manipulateData's argument)."""
    values = _source_values(env, cmd.source, ctx)
    target = accessor(env, cmd.target, ctx)
    return target.change(lambda root: nbt_ops.modify(root, cmd.path, cmd.mode, values, cmd.index))


def _source_values(env, source, ctx) -> list:
    """``value V``, ``from SOURCE [PATH]`` (copies, so the target never aliases them) or
    ``string SOURCE [PATH] [START] [END]``."""
    if isinstance(source, ast.SourceValue):
        return [source.value]
    root = accessor(env, source.source, ctx).read()
    found = [nbt_ops.copy_tag(v) for v in ([root] if source.path is None else nbt_ops.get(root, source.path))]
    if isinstance(source, ast.SourceString):
        return nbt_ops.string_source(found, source.start, source.end)
    return found


def count_matching(env, cond: ast.IfData, ctx) -> int:
    """``if data TARGET PATH``: the number of tags the path matches (0 fails the test, never an error)."""
    return nbt_ops.count_matching(accessor(env, cond.source, ctx).read(), cond.path)


def macro_arguments(env, target: ast.DataTarget, path: ast.NbtPath | None, ctx) -> Compound:
    """``function F with TARGET [PATH]``: the compound at PATH (FunctionCommand.getArgumentTag).
    Every failure is reported: like a missing macro key, it is a pack mistake."""
    try:
        root = accessor(env, target, ctx).read()
        found = [root] if path is None else nbt_ops.get(root, path)
    except CommandFailure as failure:
        failure.report = True
        raise
    if len(found) > 1:
        raise CommandFailure("commands.data.get.multiple", report=True)
    if not isinstance(found[0], dict):
        raise CommandFailure("dpemu.macro.not_compound", type(found[0]).__name__, report=True)
    return found[0]


# ---------------------------------------------------------------------- execute store
def store(target: DataAccessor, sub: ast.StoreData, stored: int) -> None:
    """Store ``stored`` as ``(TYPE)(stored * SCALE)`` at the path; every failure is silent
    (ExecuteCommand.storeData)."""
    axis = _position_axis(target, sub)
    if axis is not None:
        _store_position(target.entity, axis, float(stores.stored_tag("double", stored, sub.scale)))
        return
    try:
        target.change(lambda root: stores.store(root, sub.path, sub.type, stored, sub.scale))
    except CommandFailure:
        pass


def _position_axis(target: DataAccessor, sub: ast.StoreData) -> int | None:
    """The axis of ``store ... entity E Pos[0|1|2] double S`` on a non-player, else None."""
    nodes = sub.path.nodes
    if (sub.type == "double" and isinstance(target, EntityAccessor) and not target.entity.is_player
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


HANDLERS = {
    ast.DataGet: data_get,
    ast.DataMerge: data_merge,
    ast.DataModify: data_modify,
    ast.DataRemove: data_remove,
}
