"""Entities as arrays for the numba VM, and the selectors it evaluates itself.

The Python entity store (:mod:`emulator.world.entities`) stays the source of truth; an
:class:`EntityMirror` copies what the VM reads and writes into arrays indexed by an entity's
*slot*, its creation index ``Entity.order``:

- ``ent[slot]`` (int64 ``[slots, ENT_WIDTH]``): ``E_TYPE`` (interned type id), ``E_TAGS`` (bits of
  the interned tags), ``E_HOLDER`` (its score holder id); ``pos[slot]`` (3 doubles);
- ``order``: the slots unsorted ``@e`` visits, in the store's order (creation order, or the
  ``--shuffle`` permutation);
- ``dirty[slot]``: set by the VM when it changed the entity's tags (``DIRTY_TAGS``), its position
  (``DIRTY_POS``) or teleported it (``DIRTY_TP``: the write-back applies the rest of ``tp``).

The layout constants live in :mod:`emulator.vm.loop` (numba's cache does not see constants change in
another module).

Synchronisation, both ways and exact:
- Python -> VM: :meth:`EntityMirror.invalidate` marks the arrays stale (the backend calls it at each
  root and after every host op that may touch entities: a final command, a store, ``summon``);
  :meth:`EntityMirror.load` rebuilds them from the store before the VM runs again.
- VM -> Python: after each VM run that changed one, :meth:`EntityMirror.store` writes the dirty
  entities back (tag sets: interned tags from the bits, other tags kept; positions; teleports).

Selectors the VM evaluates (:meth:`EntityMirror.selector`): ``@e``, ``@a``, ``@s`` with ``type``
(``!`` too, no ``#`` tags), ``tag`` (several, ``!``; not the empty ``tag=``), ``scores``, and for
``@e``/``@a`` ``limit`` with ``sort=arbitrary``. A selector row is ``[kind, required tag bits,
forbidden tag bits, limit, first test, test count]``; its tests are rows of ``tests``:
``[TEST_SCORE, objective, lo, hi]`` or ``[TEST_TYPE, type id, negated, 0]``. Every other selector
stays with the host (returns None).
"""
from __future__ import annotations

import numpy as np

from mcfunction_parser import ast
from emulator.world.semantics import INT_MAX, INT_MIN
from emulator.vm.loop import (
    DIRTY_POS, DIRTY_TAGS, DIRTY_TP, E_HOLDER, E_TAGS, E_TYPE, ENT_WIDTH, KIND_A, KIND_E, KIND_S, PLAYER_TYPE,
    SEL_WIDTH, TEST_SCORE, TEST_TYPE,
)
from emulator.world import teleport

MAX_TAGS = 63  # bits of an int64 mask
_KINDS = {"e": KIND_E, "a": KIND_A, "s": KIND_S}


class EntityMirror:
    def __init__(self, scoreboard) -> None:
        self.scoreboard = scoreboard  # objectives of `scores=` are interned here
        self.bits: dict[str, int] = {}  # tag -> bit index
        self.types: dict[str, int] = {"minecraft:player": PLAYER_TYPE}
        self.sel_rows: list[list[int]] = []
        self.test_rows: list[list[int]] = []
        self._selector_ids: dict[tuple, int] = {}
        self._sel_arrays: tuple | None = None
        self.entities: dict[int, object] = {}  # slot -> Entity (the store's and every executor)
        self.ent = np.zeros((16, ENT_WIDTH), dtype=np.int64)
        self.pos = np.zeros((16, 3), dtype=np.float64)
        self.dirty = np.zeros(16, dtype=np.uint8)
        self.order = np.zeros(0, dtype=np.int64)
        self.stale = True

    # ------------------------------------------------------------------ compile time
    def bit(self, tag: str) -> int | None:
        """The tag's bit, interning it; None when the table is full."""
        index = self.bits.get(tag)
        if index is None and len(self.bits) < MAX_TAGS:
            index = self.bits[tag] = len(self.bits)
            self.stale = True  # entities carrying it need their bit
        return index

    def type_id(self, type_name: str) -> int:
        index = self.types.get(type_name)
        if index is None:
            index = self.types[type_name] = len(self.types)
        return index

    def selector(self, target) -> int | None:
        """The selector table row of ``target`` when the VM can evaluate it, else None."""
        if not isinstance(target, ast.Selector) or target.variable not in _KINDS:
            return None
        kind = _KINDS[target.variable]
        masks, tests, limit = [0, 0], [], INT_MAX
        for arg in target.args:
            if arg.key == "tag" and arg.value:
                bit = self.bit(arg.value)
                if bit is None:
                    return None
                masks[int(arg.negated)] |= 1 << bit
            elif arg.key == "type" and not arg.value.startswith("#"):
                tests.append((TEST_TYPE, self.type_id(arg.value), int(arg.negated), 0))
            elif arg.key == "scores":
                for objective, bounds in arg.value:
                    lo = INT_MIN if bounds.lo is None else max(INT_MIN, bounds.lo)
                    hi = INT_MAX if bounds.hi is None else min(INT_MAX, bounds.hi)
                    tests.append((TEST_SCORE, self.scoreboard.objective_id(objective), lo, hi))
            elif arg.key == "limit" and kind != KIND_S:
                limit = int(arg.value)
            elif not (arg.key == "sort" and arg.value == "arbitrary"):
                return None
        key = (kind, masks[0], masks[1], limit, tuple(tests))
        index = self._selector_ids.get(key)
        if index is None:
            index = self._selector_ids[key] = len(self.sel_rows)
            self.sel_rows.append([kind, masks[0], masks[1], limit, len(self.test_rows), len(tests)])
            self.test_rows.extend(list(t) for t in tests)
            self._sel_arrays = None
        return index

    def selector_arrays(self) -> tuple[np.ndarray, np.ndarray]:
        """``(selectors int64[n, SEL_WIDTH], tests int64[m, 4])`` for the VM."""
        if self._sel_arrays is None:
            sels = np.array(self.sel_rows or [[0] * SEL_WIDTH], dtype=np.int64).reshape(-1, SEL_WIDTH)
            tests = np.array(self.test_rows or [[0] * 4], dtype=np.int64).reshape(-1, 4)
            self._sel_arrays = (sels, tests)
        return self._sel_arrays

    # ------------------------------------------------------------------ run time
    def entity(self, slot: int):
        return self.entities[slot]

    def invalidate(self) -> None:
        self.stale = True

    def load(self, state) -> None:
        """Rebuild the arrays from the store if Python may have changed entities since."""
        if not self.stale:
            return
        self.stale = False
        known = dict(state.executors)
        known.update((e.order, e) for e in state.entities.entities)
        self.entities = known
        size = max(known, default=-1) + 1
        if size > self.ent.shape[0]:
            size = max(size, 2 * self.ent.shape[0])
            self.ent = np.zeros((size, ENT_WIDTH), dtype=np.int64)
            self.pos = np.zeros((size, 3), dtype=np.float64)
            self.dirty = np.zeros(size, dtype=np.uint8)
        sb = self.scoreboard
        bits = self.bits
        for slot in sorted(known):  # holders interned in creation order
            entity = known[slot]
            row = self.ent[slot]
            row[E_TYPE] = self.type_id(entity.type)
            row[E_TAGS] = sum(1 << b for t, b in bits.items() if t in entity.tags)
            row[E_HOLDER] = sb.holder_id(entity.score_holder)
            self.pos[slot] = entity.pos
        self.order = np.array([e.order for e in state.entities.entities], dtype=np.int64)

    def store(self) -> None:
        """After a VM run: write what the VM changed back into the entities."""
        changed = np.flatnonzero(self.dirty)
        if not changed.size:
            return
        for slot in changed.tolist():
            entity, flags = self.entities[slot], int(self.dirty[slot])
            if flags & DIRTY_TAGS:
                bits = int(self.ent[slot, E_TAGS])
                entity.tags = {t for t in entity.tags if t not in self.bits} | {
                    t for t, b in self.bits.items() if bits >> b & 1}
            pos = tuple(float(v) for v in self.pos[slot])
            if flags & DIRTY_TP:  # the rest of `tp`: its own rotation wrapped, no vertical motion
                teleport.apply(entity, teleport.to_entity(teleport.Destination(pos, entity.yaw, entity.pitch)))
            elif flags & DIRTY_POS:
                entity.pos = pos
        self.dirty[changed] = 0
