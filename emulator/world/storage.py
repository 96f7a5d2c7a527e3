"""Command storage (``data ... storage ID``), with the accessor semantics of the game.

``CommandStorage`` maps resource ids to compounds.
- ``get(id)``: the live compound, or a new empty one (not stored) for an unknown id.
- ``modify(id, change)``: run ``change(root)`` on the live compound (or a new one) and store the
  result; like the game, a failing change leaves partial edits of an existing storage in place
  and stores nothing for a new id. Storing an empty compound removes the id.
- ``ids()``: the ids holding data (``data get storage`` tab completion in the game).

``StorageData`` is the world's dict of them: its ``version`` counts the changes made through
``CommandStorage`` and its own item assignment (the numba VM mirrors numeric leaves and reads
them again after a change: change storage through these, not by editing a stored compound).

Source: decompiled 1.21 world/level/storage/CommandStorage.java, server/commands/data/StorageDataAccessor.java.
"""
from __future__ import annotations

from typing import Callable

from mcfunction_parser.nbt import Compound


class StorageData(dict):
    """Storage id -> compound, with a ``version`` bumped at each change."""

    version = 0

    def changed(self) -> None:
        self.version += 1

    def __setitem__(self, key, value) -> None:
        super().__setitem__(key, value)
        self.changed()

    def __delitem__(self, key) -> None:
        super().__delitem__(key)
        self.changed()

    def pop(self, *args):
        self.changed()
        return super().pop(*args)

    def clear(self) -> None:
        super().clear()
        self.changed()

    def update(self, *args, **kwargs) -> None:
        super().update(*args, **kwargs)
        self.changed()


class CommandStorage:
    def __init__(self, data: dict[str, Compound] | None = None) -> None:
        self._data: dict[str, Compound] = StorageData() if data is None else data  # a caller's dict is shared

    def get(self, storage_id: str) -> Compound:
        return self._data.get(storage_id, Compound())

    def set(self, storage_id: str, root: Compound) -> None:
        """``CommandStorage.Container.put``: an empty compound removes the id."""
        if root:
            self._data[storage_id] = root
        else:
            self._data.pop(storage_id, None)

    def modify(self, storage_id: str, change: Callable[[Compound], object]):
        root = self.get(storage_id)
        try:
            result = change(root)
        finally:  # a failed change may have edited the live compound
            if isinstance(self._data, StorageData):
                self._data.changed()
        self.set(storage_id, root)
        return result

    def ids(self) -> list[str]:
        return sorted(self._data)
