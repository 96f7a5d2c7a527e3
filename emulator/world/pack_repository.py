"""The server's data packs as ``datapack`` and ``reload`` see them (PackRepository): the packs
available, by id, and the ones selected, in the order they stack.

Ids as the game makes them: ``vanilla`` (built in, required: a selection always holds it,
PackRepository.rebuildSelected) and ``file/NAME`` for each pack loaded, NAME being its folder's or
zip file's name (FolderRepositorySource.createDiscoveredFilePackInfo). The world starts with every
loaded pack selected, in the order given, above vanilla. The game's feature packs (``bundle``,
``trade_rebalance`` ...) are not modelled.

A command that changes the selection asks for a reload (:attr:`PackRepository.pending`); the runtime
carries it out (:meth:`emulator.runtime.server.Runtime.apply_reload`).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

VANILLA = "vanilla"
FILE_PREFIX = "file/"


def pack_id(root: Path) -> str:
    """``file/`` and the pack's folder or zip file name."""
    return FILE_PREFIX + (root.name or root.resolve().name)


@dataclass
class PackRepository:
    available: dict[str, list[Path]] = field(default_factory=dict)  # id -> the pack roots of that name
    selected: list[str] = field(default_factory=lambda: [VANILLA])
    pending: list[str] | None = None  # the selection the next reload loads; None: no reload asked for
    asked_by: tuple = ()  # the call stack (Frames, the root first) of the command that first asked for it

    @classmethod
    def from_roots(cls, roots) -> "PackRepository":
        repository = cls()
        for root in roots:
            repository.available.setdefault(pack_id(Path(root)), []).append(Path(root))
        repository.selected = [VANILLA, *repository.available]
        return repository

    @property
    def current(self) -> list[str]:
        """The selection as commands see it: a reload asked for is in place when its command returns."""
        return self.selected if self.pending is None else self.pending

    def ids(self) -> list[str]:
        """Every available id, sorted as the game's TreeMap of them."""
        return sorted([VANILLA, *self.available])

    def knows(self, pack: str) -> bool:
        return pack == VANILLA or pack in self.available

    def reload(self, selection: list[str], frames: tuple = ()) -> None:
        """Ask for a reload of ``selection`` (by the command running in ``frames``); vanilla stays
        (required, at the bottom)."""
        if self.pending is None:
            self.asked_by = frames
        self.pending = selection if VANILLA in selection else [VANILLA, *selection]

    def roots(self, selection: list[str]) -> list[Path]:
        """The pack roots of ``selection``, bottom first (vanilla is no file here)."""
        return [root for pack in selection if pack != VANILLA for root in self.available[pack]]
