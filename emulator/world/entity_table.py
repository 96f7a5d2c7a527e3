"""The entity table: the state of every entity that packs touch each tick, as arrays that the numba
VM reads and writes in place and that :class:`emulator.world.entities.Entity` reads and writes
through views (one copy, nothing mirrored or rebuilt).

Rows are *slots*: an entity's creation index (``Entity.order``); a killed entity keeps its slot (a
context made for it still reaches it, as the game's source keeps its entity object).

- ``ints`` (int64 ``[slots, EI_WIDTH]``): ``EI_TYPE`` (interned type id, the player is
  ``PLAYER_TYPE``), ``EI_HOLDER`` (its score holder's id in the scoreboard, -1 without one),
  ``EI_ALIVE`` (1 until killed), ``EI_DIM`` (its level, :class:`emulator.world.dimensions.Levels`'s
  number), ``EI_JOIN`` (a player's place in the server's player list: the order of joining), what
  the selector arguments ``name``, ``team``, ``gamemode`` and ``level`` compare: ``EI_NAME`` (its
  display name, interned: :meth:`EntityTable.name_id`), ``EI_TEAM`` (its team's name, interned
  likewise; -1 without a team), ``EI_LIVING`` (1 for a LivingEntity: ``team`` tests only those),
  ``EI_GAMEMODE`` (a player's game mode, its index in :data:`GAMEMODES`) and ``EI_XP`` (a player's
  experience level); the entity writes them when they change (:class:`emulator.world.entities.Entity`);
  what ``execute on vehicle|passengers`` follows: ``EI_VEHICLE`` (its vehicle's slot + 1, 0 when it
  rides nothing) and ``EI_SEAT`` (when it last got on or off, counted by :attr:`EntityTable.seats`:
  a vehicle's passengers in that order are its ``passengers`` list);
- ``floats`` (float64 ``[slots, EF_WIDTH]``): position ``EF_X..EF_Z``, motion ``EF_MX..EF_MZ``,
  rotation ``EF_YAW``/``EF_PITCH`` (float32 values, exact in a double), the hitbox's half width and
  height and the eye height ``EF_HALF``/``EF_HEIGHT``/``EF_EYE`` (``Entity.sizes``, kept by ``attach``
  and ``load_nbt``); a display entity's ``transformation`` from ``EF_TRANSFORM``: translation (3),
  left rotation (4), scale (3), right rotation (4), float32 values (``display.transformation_columns``;
  the entity's NBT reads them there);
- ``tags`` (int64 ``[slots, words]``): a bitset per entity over the interned tag names (tag ``t`` is
  bit ``t & 63`` of word ``t >> 6``); interning a tag past the last word adds one, so there is no
  limit on the tags of an entity or of a pack;
- ``order[:count]``: the living entities' slots in the order unsorted ``@e`` visits them: level by
  level (``EI_DIM``), each level's in the order they came into it; ``live`` (int64 ``[1]``) holds
  ``count`` for the VM, which keeps ``order`` whole (an entity coming or going changes no array it holds);
- ``random`` (int64 ``[1]``): the state of the ``java.util.Random`` that ``sort=random`` and ``@r``
  shuffle with (:mod:`emulator.world.java_random`), seeded by the store.

The column numbers are literals of :mod:`emulator.vm.loop` too, written there from here by
:mod:`emulator.vm.generate` (numba's cache does not see a constant of another module change).
"""
from __future__ import annotations

from collections.abc import MutableSet
from typing import Callable, Iterable

import numpy as np

from emulator.world.dimensions import Levels
from emulator.world.display import DISPLAY_TYPES

EI_TYPE, EI_HOLDER, EI_ALIVE, EI_DIM, EI_JOIN, EI_NAME, EI_TEAM, EI_LIVING, EI_GAMEMODE, EI_XP, EI_VEHICLE, EI_SEAT = range(12)
EI_WIDTH = 12
GAMEMODES = ("survival", "creative", "adventure", "spectator")  # GameType's ids, in its order
EF_X, EF_Y, EF_Z, EF_MX, EF_MY, EF_MZ, EF_YAW, EF_PITCH, EF_HALF, EF_HEIGHT, EF_EYE, EF_TRANSFORM = range(12)
EF_WIDTH = EF_TRANSFORM + 14
# type ids interned first: the player, then the display entities (their transformation columns)
PLAYER_TYPE = 0
FIRST_DISPLAY_TYPE, LAST_DISPLAY_TYPE = 1, 1 + len(DISPLAY_TYPES) - 1
LAYOUT = {name: value for name, value in globals().items()
          if name.startswith(("EI_", "EF_")) or name in ("PLAYER_TYPE", "FIRST_DISPLAY_TYPE", "LAST_DISPLAY_TYPE")}

_MASK64 = 0xFFFFFFFFFFFFFFFF


def _bit(tag: int) -> np.int64:
    return np.int64(1) << np.int64(tag & 63)


LATEST_RELEASE = (1, 21, 11)  # what a table or store runs as until the runtime says


class EntityTable:
    """The arrays, the interned tag and type names, and the slot -> entity handles."""

    def __init__(self, capacity: int = 16) -> None:
        self.ints = np.zeros((capacity, EI_WIDTH), dtype=np.int64)
        self.floats = np.zeros((capacity, EF_WIDTH), dtype=np.float64)
        self.tags = np.zeros((capacity, 1), dtype=np.int64)
        self.order = np.zeros(capacity, dtype=np.int64)
        self.random = np.zeros(1, dtype=np.int64)
        self.size = 0  # slots used
        self.seats = 0  # the times an entity got on or off a vehicle (EI_SEAT)
        self.count = 0  # living entities, order[:count]
        self.live = np.zeros(1, dtype=np.int64)  # count, as the VM reads it
        self.alive_writes = 0  # EI_ALIVE written after the entity came (what is derived from it is kept until this grows)
        self.handles: list = []  # slot -> Entity
        self.tag_ids: dict[str, int] = {}
        self.tag_names: list[str] = []
        self.type_ids: dict[str, int] = {"minecraft:player": PLAYER_TYPE}
        self.type_ids.update((name, FIRST_DISPLAY_TYPE + i) for i, name in enumerate(DISPLAY_TYPES))
        self.names: dict[str, int] = {}  # display names and team names -> their number (EI_NAME, EI_TEAM)
        self.uuids: dict[tuple, list] = {}  # UUID -> the living entities that have it
        self.intern_holder: Callable[[str], int] | None = None  # the scoreboard's holder_id
        self.levels = Levels()  # the numbers of EI_DIM (the packs' dimensions are added at load)
        self.release = LATEST_RELEASE  # the release the packs run as (what its entities save: EntityStore.version)

    # ------------------------------------------------------------------ names
    def tag_id(self, name: str) -> int:
        """The tag's number, interning it (a new bitset word when the last one is full)."""
        index = self.tag_ids.get(name)
        if index is None:
            index = self.tag_ids[name] = len(self.tag_names)
            self.tag_names.append(name)
            if index >> 6 >= self.tags.shape[1]:
                self.tags = np.concatenate([self.tags, np.zeros_like(self.tags)], axis=1)
        return index

    def type_id(self, name: str) -> int:
        index = self.type_ids.get(name)
        if index is None:
            index = self.type_ids[name] = len(self.type_ids)
        return index

    def name_id(self, name: str | None) -> int:
        """The number of a display or team name (``name=``, ``team=``), interning it; -1 for None (no team)."""
        if name is None:
            return -1
        index = self.names.get(name)
        if index is None:
            index = self.names[name] = len(self.names)
        return index

    def intern_names_of(self, other: "EntityTable") -> None:
        """Intern ``other``'s tag, type, display and team names, in its order, into this empty table
        (a program compiled against ``other`` holds their numbers)."""
        if self.tag_names or self.names or len(self.type_ids) > LAST_DISPLAY_TYPE + 1:  # the player and the displays
            raise ValueError("names are interned into an empty entity table only")
        for name in other.tag_names:
            self.tag_id(name)
        for name in other.type_ids:
            self.type_id(name)
        for name in other.names:
            self.name_id(name)

    # ------------------------------------------------------------------ rows
    def new_slot(self, entity, type_name: str, holder: str) -> int:
        """A row for ``entity`` (not yet in the iteration order: see :meth:`insert`)."""
        slot = self.size
        if slot >= self.ints.shape[0]:
            self._grow(2 * self.ints.shape[0])
        self.size += 1
        self.handles.append(entity)
        self.ints[slot, EI_TYPE] = self.type_id(type_name)
        self.ints[slot, EI_HOLDER] = -1 if self.intern_holder is None else self.intern_holder(holder)
        self.ints[slot, EI_ALIVE] = 1
        return slot

    def _grow(self, capacity: int) -> None:
        def grown(array: np.ndarray) -> np.ndarray:
            out = np.zeros((capacity,) + array.shape[1:], dtype=array.dtype)
            out[:array.shape[0]] = array
            return out
        self.ints, self.floats, self.tags, self.order = (grown(a) for a in (self.ints, self.floats, self.tags, self.order))

    def level_span(self, level: int) -> tuple[int, int]:
        """The indexes ``[start, end)`` of ``order`` that hold level ``level``'s entities (where a
        new one of that level goes: ``end``)."""
        n = self.count
        if n == 0 or self.ints[self.order[n - 1], EI_DIM] < level:
            return n, n
        if self.ints[self.order[0], EI_DIM] == level == self.ints[self.order[n - 1], EI_DIM]:
            return 0, n  # every entity in one level (the usual world)
        levels = self.ints[self.order[:n], EI_DIM]  # ascending: the order is grouped by level
        return int(np.searchsorted(levels, level, "left")), int(np.searchsorted(levels, level, "right"))

    def insert(self, index: int, slot: int) -> None:
        """Put ``slot`` at ``index`` of the iteration order."""
        n = self.count
        self.order[index + 1:n + 1] = self.order[index:n].copy()
        self.order[index] = slot
        self.count = self.live[0] = n + 1

    def remove(self, index: int) -> None:
        """Take the entity at ``index`` out of the iteration order."""
        n = self.count
        self.order[index:n - 1] = self.order[index + 1:n].copy()
        self.count = self.live[0] = n - 1

    def index_uuid(self, entity, old: tuple | None, new: tuple | None) -> None:
        """Keep :attr:`uuids` up to date: ``entity``'s UUID went from ``old`` to ``new`` (None: not living)."""
        if old is not None and entity in self.uuids.get(old, ()):
            self.uuids[old].remove(entity)
            if not self.uuids[old]:
                del self.uuids[old]
        if new is not None and self.ints[entity.order, EI_ALIVE]:
            self.uuids.setdefault(new, []).append(entity)

    def living(self) -> np.ndarray:
        return self.order[:self.count]

    # ------------------------------------------------------------------ tags of one slot
    def has_tag(self, slot: int, name: str) -> bool:
        index = self.tag_ids.get(name)
        return index is not None and bool(self.tags[slot, index >> 6] & _bit(index))

    def set_tag(self, slot: int, name: str, on: bool) -> None:
        index = self.tag_id(name)
        if on:
            self.tags[slot, index >> 6] |= _bit(index)
        else:
            self.tags[slot, index >> 6] &= ~_bit(index)

    def tag_numbers(self, slot: int) -> Iterable[int]:
        for w, word in enumerate(self.tags[slot].tolist()):
            word &= _MASK64
            while word:
                low = word & -word
                yield (w << 6) + low.bit_length() - 1
                word ^= low

    def tag_count(self, slot: int) -> int:
        return sum((word & _MASK64).bit_count() for word in self.tags[slot].tolist())


class TagSet(MutableSet):
    """An entity's tags: a set of names viewing its bitset row (iterated in interning order)."""

    __slots__ = ("table", "slot")

    def __init__(self, table: EntityTable, slot: int) -> None:
        self.table = table
        self.slot = slot

    def __contains__(self, name) -> bool:
        return self.table.has_tag(self.slot, name)

    def __iter__(self):
        names = self.table.tag_names
        return (names[t] for t in self.table.tag_numbers(self.slot))

    def __len__(self) -> int:
        return self.table.tag_count(self.slot)

    def add(self, name: str) -> None:
        self.table.set_tag(self.slot, name, True)

    def discard(self, name: str) -> None:
        if name in self.table.tag_ids:
            self.table.set_tag(self.slot, name, False)

    def replace(self, names: Iterable[str]) -> None:
        self.table.tags[self.slot] = 0
        for name in names:
            self.add(name)

    def __repr__(self) -> str:
        return f"TagSet({sorted(self)!r})"
