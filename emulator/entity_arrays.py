"""Entity tags mirrored as arrays for the numba VM (``tag @s add|remove T``, ``if entity @s[tag=..]``).

The Python entity store stays the source of truth. Tags the compiler meets in those two forms are
interned to bits (at most :data:`MAX_TAGS`; later tags leave their commands to the host). For each
entity that runs as ``@s`` in a context (its creation index ``Entity.order``), ``tags[order]`` holds
the bits of its interned tags:

- Python -> VM: a context made for an entity loads its bits; world commands that may change tags
  bump ``WorldState.tags_version`` (:mod:`emulator.world_entities`), and the backend reloads the
  bits of every mirrored entity before the VM runs again.
- VM -> Python: the VM marks ``dirty[order]`` when it changes bits; after each VM run the backend
  rewrites those entities' tag sets (interned tags from the bits, other tags kept).
"""
from __future__ import annotations

import numpy as np

MAX_TAGS = 31  # masks are int32 instruction operands (sign bit unused)


class TagMirror:
    def __init__(self) -> None:
        self.bits: dict[str, int] = {}  # tag -> bit index
        self.tags = np.zeros(16, dtype=np.int64)
        self.dirty = np.zeros(16, dtype=np.uint8)
        self.entities: dict[int, object] = {}  # order -> Entity, the mirrored ones
        self.version = -1  # WorldState.tags_version last loaded

    def bit(self, tag: str) -> int | None:
        """The tag's bit, interning it; None when the table is full."""
        index = self.bits.get(tag)
        if index is None and len(self.bits) < MAX_TAGS:
            index = self.bits[tag] = len(self.bits)
        return index

    def mask(self, entity) -> int:
        return sum(1 << b for t, b in self.bits.items() if t in entity.tags)

    def track(self, entity) -> None:
        """Mirror ``entity`` (it runs as ``@s`` in a context)."""
        order = entity.order
        if order >= self.tags.shape[0]:
            size = max(order + 1, 2 * self.tags.shape[0])
            self.tags = np.concatenate([self.tags, np.zeros(size - self.tags.shape[0], dtype=np.int64)])
            self.dirty = np.concatenate([self.dirty, np.zeros(size - self.dirty.shape[0], dtype=np.uint8)])
        self.entities[order] = entity
        self.tags[order] = self.mask(entity)

    def load(self, version: int) -> None:
        """Before a VM run: reload every mirrored entity's bits if Python changed tags since."""
        if version != self.version:
            self.version = version
            for order, entity in self.entities.items():
                self.tags[order] = self.mask(entity)

    def store(self) -> None:
        """After a VM run: write the bits the VM changed back into the entities' tag sets."""
        changed = np.flatnonzero(self.dirty)
        if not changed.size:
            return
        for order in changed.tolist():
            entity, bits = self.entities[order], int(self.tags[order])
            entity.tags = {t for t in entity.tags if t not in self.bits} | {
                t for t, b in self.bits.items() if bits >> b & 1}
        self.dirty[changed] = 0
