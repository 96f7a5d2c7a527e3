"""Numbers in command storage that the numba VM reads and writes itself: storage leaves.

A leaf is a storage id and a path of compound keys (``phys:flags contact``) that a command of the
program names with a number: ``data modify storage S P set value N``, ``execute if data storage S
{K:N}``, ``data get storage S P [scale]`` and ``execute store ... storage S P TYPE SCALE``. The VM
keeps each leaf in two arrays: ``meta[leaf] = [type, dirty, exists]`` (``type``: the ``LEAF_*`` type of
the number there, 0 when the path does not lead through compounds to a byte, short, int, float or
double; ``exists``: 1 when it leads to any tag, for ``execute if|unless data storage S a.b.c``)
and ``values[leaf]`` (the number, exact in a double). The VM writes numbers only where one is, so
it never changes what exists.

Python's compounds stay the storage (``WorldState.storage``): :meth:`StorageLeaves.read` mirrors
them into the arrays when the storage changed (its ``version``), before the VM runs, and
:meth:`StorageLeaves.write_back` puts the numbers the VM wrote (``dirty``) back into them when the
VM stops, before Python reads anything. A leaf that is not a number there (a missing key, a list,
a long) sends the command to the host, which creates or reads it as the game does.
"""
from __future__ import annotations

import numpy as np

from emulator.vm.loop import LEAF_BYTE, LEAF_DOUBLE, LEAF_FLOAT, LEAF_INT, LEAF_SHORT
from emulator.world.storage import StorageData
from mcfunction_parser import ast
from mcfunction_parser.nbt import Byte, Compound, Double, Float, Int, Short

LEAF_TYPES = {Byte: LEAF_BYTE, Short: LEAF_SHORT, Int: LEAF_INT, Float: LEAF_FLOAT, Double: LEAF_DOUBLE}
TAGS = {code: tag for tag, code in LEAF_TYPES.items()}
STORE_TYPES = {"byte": LEAF_BYTE, "short": LEAF_SHORT, "int": LEAF_INT, "float": LEAF_FLOAT, "double": LEAF_DOUBLE}


def key_path(path: ast.NbtPath | None) -> tuple[str, ...] | None:
    """The keys of a path made only of compound keys (``a.b.c``), else None."""
    if path is None or not path.nodes or not all(isinstance(n, ast.PathKey) for n in path.nodes):
        return None
    return tuple(n.name for n in path.nodes)


def number_code(tag) -> int:
    """The LEAF_* type of an NBT number the VM mirrors, 0 for anything else."""
    return LEAF_TYPES.get(type(tag), 0)


class StorageLeaves:
    def __init__(self) -> None:
        self.leaves: list[tuple[str, tuple[str, ...]]] = []
        self._ids: dict[tuple[str, tuple[str, ...]], int] = {}
        self.meta = np.zeros((1, 3), dtype=np.int64)
        self.values = np.zeros(1, dtype=np.float64)
        self.version = -1  # the storage version last read

    def leaf(self, storage_id: str, keys: tuple[str, ...]) -> int:
        """The leaf of ``storage_id`` at ``keys`` (interned; read at the next :meth:`read`)."""
        key = (storage_id, keys)
        index = self._ids.get(key)
        if index is None:
            index = self._ids[key] = len(self.leaves)
            self.leaves.append(key)
            if index >= self.meta.shape[0]:
                self.meta = np.concatenate([self.meta, np.zeros_like(self.meta)])
                self.values = np.concatenate([self.values, np.zeros_like(self.values)])
            self.version = -1
        return index

    def read(self, storage: StorageData) -> None:
        """Mirror every leaf from the compounds, when the storage changed since the last read."""
        if isinstance(storage, StorageData) and storage.version == self.version:
            return
        for index, (storage_id, keys) in enumerate(self.leaves):
            tag = storage.get(storage_id)
            for key in keys:
                tag = tag.get(key) if isinstance(tag, Compound) else None
            self.meta[index, 0] = number_code(tag)
            self.meta[index, 1] = 0
            self.meta[index, 2] = tag is not None
            self.values[index] = float(tag) if self.meta[index, 0] else 0.0
        self.version = getattr(storage, "version", -1)

    def write_back(self, storage: StorageData) -> None:
        """Put the numbers the VM wrote into the compounds (their keys exist: the VM writes only
        where a number was); the mirror stays current."""
        if not self.leaves or not self.meta[:, 1].any():
            return
        for index in np.flatnonzero(self.meta[:, 1]).tolist():
            storage_id, keys = self.leaves[index]
            parent = storage[storage_id]
            for key in keys[:-1]:
                parent = parent[key]
            code = int(self.meta[index, 0])
            value = self.values[index]
            parent[keys[-1]] = TAGS[code](float(value) if code in (LEAF_FLOAT, LEAF_DOUBLE) else int(value))
            self.meta[index, 1] = 0
