"""Numbers in command storage that the numba VM reads and writes itself: storage leaves.

A leaf is a storage id and a path of compound keys and list indices (``phys:flags contact``,
``bs:ctx _.coeffs[0]``, ``bs:data stream[-1]._``) that a command of the program names with a number: ``data modify storage S P set value N``, ``execute if data storage S
{K:N}``, ``data get storage S P [scale]`` and ``execute store ... storage S P TYPE SCALE``. The VM
keeps each leaf in two arrays: ``meta[leaf] = [type, dirty, exists]`` (``type``: the ``LEAF_*`` type of
the number there, 0 when the path does not lead through compounds and lists to a byte, short, int,
float or double; ``exists``: 1 when it leads to any tag, for ``execute if|unless data storage S
a.b.c``, 2 when that tag is a list's element: the VM writes a number of its own type only, since a
list before 1.21.5 refuses another type (ListTag.setTag), and another goes to the host) and
``values[leaf]`` (the number, exact in a double). The VM writes numbers only where one is, so it
never changes what exists. A list index counts from the end when negative (NbtPathArgument's
IndexedElementNode), so two leaves may name one number (``l[0]`` and ``l[-1]`` of a list of one):
such leaves, and the elements of arrays (which convert what is stored into them), are read as no
number, and their commands go to the host.

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
from mcfunction_parser.nbt import ARRAY_TYPES, Byte, Compound, Double, Float, Int, List, Short

LEAF_TYPES = {Byte: LEAF_BYTE, Short: LEAF_SHORT, Int: LEAF_INT, Float: LEAF_FLOAT, Double: LEAF_DOUBLE}
TAGS = {code: tag for tag, code in LEAF_TYPES.items()}
STORE_TYPES = {"byte": LEAF_BYTE, "short": LEAF_SHORT, "int": LEAF_INT, "float": LEAF_FLOAT, "double": LEAF_DOUBLE}


def key_path(path: ast.NbtPath | None) -> tuple[str | int, ...] | None:
    """The steps of a path of compound keys (str) and list indices (int) that starts with a key
    (``a.b.c``, ``a.l[0]``, ``l[-1].x``), else None."""
    if path is None or not path.nodes or not isinstance(path.nodes[0], ast.PathKey):
        return None
    steps = []
    for node in path.nodes:
        if isinstance(node, ast.PathKey):
            steps.append(node.name)
        elif isinstance(node, ast.PathIndex):
            steps.append(node.index)
        else:
            return None
    return tuple(steps)


def _resolve(tag, keys: tuple[str | int, ...]):
    """(the tag at ``keys`` from ``tag`` or None, its container, the key or index in it)."""
    parent, step = None, None
    for key in keys:
        parent = tag
        if isinstance(key, str):
            tag = tag.get(key) if isinstance(tag, Compound) else None
            step = key
        elif isinstance(tag, (List, *ARRAY_TYPES)) and -len(tag) <= key < len(tag):
            step = key % len(tag)
            tag = tag[step]
        else:
            tag = None
        if tag is None:
            return None, None, None
    return tag, parent, step


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
        places: dict[tuple[int, str | int], int] = {}  # (container, key or index) -> the first leaf there
        for index, (storage_id, keys) in enumerate(self.leaves):
            tag, parent, step = _resolve(storage.get(storage_id), keys)
            self.meta[index, 0] = number_code(tag) if not isinstance(parent, ARRAY_TYPES) else 0
            self.meta[index, 1] = 0
            self.meta[index, 2] = 0 if tag is None else 2 if isinstance(parent, List) else 1
            self.values[index] = float(tag) if self.meta[index, 0] else 0.0
            if tag is not None:
                first = places.setdefault((id(parent), step), index)
                if first != index:  # two leaves, one number: the host reads and writes it
                    self.meta[[first, index], 0] = 0
        self.version = getattr(storage, "version", -1)

    def write_back(self, storage: StorageData) -> None:
        """Put the numbers the VM wrote into the compounds and lists (their paths exist: the VM writes
        only where a number was); the mirror stays current."""
        if not self.leaves or not self.meta[:, 1].any():
            return
        for index in np.flatnonzero(self.meta[:, 1]).tolist():
            storage_id, keys = self.leaves[index]
            _, parent, step = _resolve(storage[storage_id], keys)
            code = int(self.meta[index, 0])
            value = self.values[index]
            parent[step] = TAGS[code](float(value) if code in (LEAF_FLOAT, LEAF_DOUBLE) else int(value))
            self.meta[index, 1] = 0
