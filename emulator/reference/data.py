"""``data`` commands, ``execute store ... storage``, ``execute if data`` and ``function ... with``,
on command storage (DataCommands, StorageDataAccessor). The NBT work is the world library's
(:mod:`emulator.world.nbt_ops`, :mod:`emulator.world.stores`); entity and block data need the
entity and block stores, which the world state does not hold yet.
"""
from __future__ import annotations

from contextlib import contextmanager

from emulator.world import nbt_ops, stores
from emulator.world.errors import CommandFailure as WorldFailure
from mcfunction_parser import ast
from mcfunction_parser.nbt import Compound

from .failure import CommandFailure
from .queue import chain
from .source import Source


@contextmanager
def world_failures(report: bool = False):
    """The world library's failures are command failures with the same message."""
    try:
        yield
    except WorldFailure as failure:
        raise CommandFailure(failure.message, report) from None


def storage_root(env, target: ast.DataTarget, create: bool) -> Compound:
    """CommandStorage.get: a missing storage reads as an empty compound."""
    if not isinstance(target, ast.StorageData):
        raise CommandFailure("entity and block data are not emulated yet", report=True)
    root = env.state.storage.get(target.id)
    if root is None:
        root = Compound()
        if create:
            env.state.storage[target.id] = root
    return root


def data_get(env, cmd: ast.DataGet, source: Source, where) -> int:
    root = storage_root(env, cmd.target, create=False)
    if cmd.path is None:
        return 1
    with world_failures():
        if cmd.scale is None:
            return stores.data_get(root, cmd.path)
        return stores.data_get_scaled(root, cmd.path, cmd.scale)


def data_merge(env, cmd: ast.DataMerge, source: Source, where) -> int:
    root = storage_root(env, cmd.target, create=True)
    with world_failures():
        return nbt_ops.data_merge(root, cmd.nbt)


def data_modify(env, cmd: ast.DataModify, source: Source, where) -> int:
    with world_failures():
        values = _source_values(env, cmd.source)
        root = storage_root(env, cmd.target, create=True)
        return nbt_ops.modify(root, cmd.path, cmd.mode, values, cmd.index)


def data_remove(env, cmd: ast.DataRemove, source: Source, where) -> int:
    root = storage_root(env, cmd.target, create=True)
    with world_failures():
        return nbt_ops.data_remove(root, cmd.path)


def _source_values(env, data_source) -> list:
    if isinstance(data_source, ast.SourceValue):
        return [data_source.value]
    root = storage_root(env, data_source.source, create=False)
    values = [root] if data_source.path is None else nbt_ops.get(root, data_source.path)
    if isinstance(data_source, ast.SourceString):
        return nbt_ops.string_source(values, data_source.start, data_source.end)
    return [nbt_ops.copy_tag(v) for v in values]


def store_data(env, sub: ast.StoreData, source: Source) -> Source:
    """``store result|success storage ID PATH TYPE SCALE``: ``(TYPE)(result x scale)`` stored on
    each result; a bad path stores nothing, silently (ExecuteCommand.storeData)."""
    root = storage_root(env, sub.target, create=True)
    want_result = sub.kind == "result"

    def store(success: bool, value: int) -> None:
        stores.store(root, sub.path, sub.type, value if want_result else int(success), sub.scale)

    return source.with_callback(chain(source.callback, store))


def count_matching(env, cond: ast.IfData) -> int:
    root = storage_root(env, cond.source, create=False)
    with world_failures():
        return nbt_ops.count_matching(root, cond.path)


def macro_arguments(env, target: ast.DataTarget, path: ast.NbtPath | None) -> Compound:
    """``function F with storage ID [PATH]``: the compound at PATH (FunctionCommand.getArgumentTag).
    Failures are reported: like a missing macro key, they are pack mistakes."""
    root = storage_root(env, target, create=False)
    if path is None:
        return root
    with world_failures(report=True):
        found = nbt_ops.get(root, path)
    if len(found) > 1:
        raise CommandFailure("This argument accepts a single NBT value", report=True)
    if not isinstance(found[0], dict):
        raise CommandFailure(f"Expected argument to be a compound, got {type(found[0]).__name__}", report=True)
    return found[0]


HANDLERS = {
    ast.DataGet: data_get,
    ast.DataMerge: data_merge,
    ast.DataModify: data_modify,
    ast.DataRemove: data_remove,
}
