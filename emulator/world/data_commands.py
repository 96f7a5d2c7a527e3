"""``data`` commands, ``execute store ... entity|storage|block`` and ``execute if data`` on any of
the three data targets, from their AST nodes.

A ``DataAccessor`` is how the game reaches a target's NBT:
- storage: the live compound (a new empty one for an unknown id), stored back on success;
- entity: a fresh NBT view, loaded back into the entity (UUID kept; players refuse);
- block: the block entity's NBT with ``x y z id`` (a block without one fails "not a block entity").
``accessor(target, world)`` builds one from a ``StorageData``/``EntityData``/``BlockData`` node;
``world`` is a :class:`World` (entity store, block map, command storage) and the execution source.

Commands (each returns the command result or raises ``CommandFailure``)
- ``data_get(acc, path=None, scale=None)``; ``data_merge(acc, nbt)``; ``data_remove(acc, path)``;
- ``data_modify(acc, path, mode, index, values)`` with ``values`` from ``source_values(acc, path)``
  or ``string_values(acc, path, start, end)`` (``from`` / ``string`` sources) or ``[value]``;
- ``if_data(acc, path)``: the match count (0 is a failed condition, never an error);
- ``store_data(acc, path, type_name, value, scale)``: silent on every failure, like the game.

Source: decompiled 1.21 server/commands/data/DataCommands.java, EntityDataAccessor.java,
BlockDataAccessor.java, StorageDataAccessor.java, server/commands/ExecuteCommand.java (storeData).
"""
from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import dataclass, field
from typing import Callable

from mcfunction_parser import ast
from mcfunction_parser.nbt import Compound
from emulator.world import nbt_ops, stores
from emulator.world.blocks import BlockMap, block_pos
from emulator.world.commands import resolve_entity
from emulator.world.entities import Entity, EntityStore, entity_nbt, modify_entity
from emulator.world.errors import CommandFailure
from emulator.world.source import Source
from emulator.world.storage import CommandStorage


@dataclass
class World:
    """What data commands reach: entities, blocks, storage, and the execution source."""

    entities: EntityStore = field(default_factory=EntityStore)
    blocks: BlockMap = field(default_factory=BlockMap)
    storage: CommandStorage = field(default_factory=CommandStorage)
    source: Source = field(default_factory=Source)
    selector_options: dict = field(default_factory=dict)  # scores / type_tags for selectors


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
    def __init__(self, entity: Entity) -> None:
        self.entity = entity

    def read(self) -> Compound:
        return entity_nbt(self.entity)

    def change(self, edit):
        return modify_entity(self.entity, edit)


class BlockAccessor(DataAccessor):
    def __init__(self, blocks: BlockMap, pos) -> None:
        self.blocks, self.pos = blocks, pos
        blocks.block_nbt(pos)  # fails now for a block without a block entity, as the game's accessor does

    def read(self) -> Compound:
        return self.blocks.block_nbt(self.pos)

    def change(self, edit):
        return self.blocks.modify_block(self.pos, edit)


def accessor(target: ast.DataTarget, world: World) -> DataAccessor:
    if isinstance(target, ast.StorageData):
        return StorageAccessor(world.storage, target.id)
    if isinstance(target, ast.EntityData):
        return EntityAccessor(resolve_entity(target.target, world.entities, world.source, **world.selector_options))
    return BlockAccessor(world.blocks, block_pos(world.source, target.pos))


def data_get(acc: DataAccessor, path: ast.NbtPath | None = None, scale: float | None = None) -> int:
    """``data get``: 1 for the whole compound, else the value (floored, sizes for non-numbers)."""
    if path is None:
        acc.read()
        return 1
    if scale is None:
        return stores.data_get(acc.read(), path)
    return stores.data_get_scaled(acc.read(), path, scale)


def data_merge(acc: DataAccessor, patch: Compound) -> int:
    return acc.change(lambda root: nbt_ops.data_merge(root, patch))


def data_remove(acc: DataAccessor, path: ast.NbtPath) -> int:
    return acc.change(lambda root: nbt_ops.data_remove(root, path))


def data_modify(acc: DataAccessor, path: ast.NbtPath, mode: str, index: int | None, values: list) -> int:
    return acc.change(lambda root: nbt_ops.modify(root, path, mode, values, index))


def source_values(acc: DataAccessor, path: ast.NbtPath | None) -> list:
    """``from SOURCE [PATH]``: the whole compound, or every tag the path selects (copies)."""
    root = acc.read()
    found = [root] if path is None else nbt_ops.get(root, path)
    return [nbt_ops.copy_tag(v) for v in found]


def string_values(acc: DataAccessor, path: ast.NbtPath | None, start: int | None, end: int | None) -> list:
    return nbt_ops.string_source(source_values(acc, path), start, end)


def if_data(acc: DataAccessor, path: ast.NbtPath) -> int:
    return nbt_ops.count_matching(acc.read(), path)


def store_data(acc: DataAccessor, path: ast.NbtPath, type_name: str, value: int, scale: float) -> int:
    """``execute store ... PATH TYPE SCALE``: how many tags changed; every failure is swallowed."""
    try:
        return acc.change(lambda root: stores.store(root, path, type_name, value, scale))
    except CommandFailure:
        return 0
