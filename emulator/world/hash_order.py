"""The iteration orders of the game's hash maps, reproduced: the score-holder map, and a
``java.util.HashMap`` keyed by ids (:func:`java_hash_map_order`: the recipe map before 1.21.2).

``Scoreboard.playerScores`` is a fastutil ``Object2ObjectOpenHashMap<String, PlayerScores>(16, 0.5F)``
and ``getTrackedPlayers()`` (what ``*`` names) streams its key set. :class:`OpenHashKeys` replays
that table: linear probing on ``HashCommon.mix(String.hashCode()) & mask``, growth when an insert
finds ``size >= maxFill``, backward-shift deletion (``shiftKeys``) and the shrink of ``removeEntry``;
:meth:`OpenHashKeys.keys` is the key-set spliterator's order (slot 0 upwards). The order therefore
depends on the history of insertions and removals, as in the game.

Sources: decompiled 1.21 world/scores/Scoreboard.java (the map, getOrCreatePlayerInfo,
resetAllPlayerScores, resetSinglePlayerScore, getTrackedPlayers); fastutil 8.5
Object2ObjectOpenHashMap (constructor, find, insert, removeEntry, shiftKeys, rehash, KeySpliterator)
and HashCommon (mix, arraySize, maxFill); java.lang.String.hashCode.
"""
from __future__ import annotations

import math

_INT_PHI = 0x9E3779B9


def java_string_hash(text: str) -> int:
    """String.hashCode: s[0]*31^(n-1) + ... over UTF-16 code units, in 32-bit arithmetic (unsigned here)."""
    h = 0
    data = text.encode("utf-16-le")
    for i in range(0, len(data), 2):
        h = (31 * h + (data[i] | data[i + 1] << 8)) & 0xFFFFFFFF
    return h


def mix(x: int) -> int:
    """HashCommon.mix: h = x * INT_PHI; h ^ (h >>> 16) (unsigned 32-bit)."""
    h = (x * _INT_PHI) & 0xFFFFFFFF
    return h ^ (h >> 16)


def array_size(expected: int, f: float) -> int:
    """HashCommon.arraySize: the next power of two of ceil(expected / f), at least 2."""
    return max(2, 1 << max(0, math.ceil(expected / f) - 1).bit_length())


def max_fill(n: int, f: float) -> int:
    """HashCommon.maxFill: min(ceil(n * f), n - 1)."""
    return min(math.ceil(n * f), n - 1)


class OpenHashKeys:
    """The key table of a fastutil Object2ObjectOpenHashMap (String keys; null never occurs)."""

    def __init__(self, expected: int = 16, f: float = 0.5) -> None:
        self.f = f
        self.n = self.min_n = array_size(expected, f)
        self.max_fill = max_fill(self.n, f)
        self.table: list[str | None] = [None] * self.n
        self.size = 0
        self._mixed: dict[str, int] = {}  # mix(hashCode) of each key (String caches its hash too)

    def __contains__(self, key: str) -> bool:
        return key in self._mixed

    def __len__(self) -> int:
        return self.size

    def add(self, key: str) -> None:
        """``computeIfAbsent``: find, else insert at the first free slot of the probe; grow
        (rehash to arraySize(size + 1)) when the size before the insert was >= maxFill."""
        if key in self._mixed:
            return
        h = mix(java_string_hash(key))
        mask = self.n - 1
        pos = h & mask
        while self.table[pos] is not None:
            pos = (pos + 1) & mask
        self.table[pos] = key
        self._mixed[key] = h
        self.size += 1
        if self.size - 1 >= self.max_fill:
            self._rehash(array_size(self.size + 1, self.f))

    def remove(self, key: str) -> None:
        """``remove``: find, clear, shift the cluster back; shrink to n/2 when n > minN,
        size < maxFill / 4 and n > 16."""
        if key not in self._mixed:
            return
        mask = self.n - 1
        pos = self._mixed[key] & mask
        while self.table[pos] != key:
            pos = (pos + 1) & mask
        del self._mixed[key]
        self.size -= 1
        self._shift_keys(pos)
        if self.n > self.min_n and self.size < self.max_fill // 4 and self.n > 16:
            self._rehash(self.n // 2)

    def _shift_keys(self, pos: int) -> None:
        table, mask = self.table, self.n - 1
        while True:
            last = pos
            pos = (last + 1) & mask
            while True:
                curr = table[pos]
                if curr is None:
                    table[last] = None
                    return
                slot = self._mixed[curr] & mask
                if (last >= slot or slot > pos) if last <= pos else (last >= slot and slot > pos):
                    break
                pos = (pos + 1) & mask
            table[last] = curr

    def _rehash(self, new_n: int) -> None:
        """Keys taken from the old table's top slot downwards, each placed by linear probing."""
        mask = new_n - 1
        table: list[str | None] = [None] * new_n
        for key in reversed(self.table):
            if key is None:
                continue
            pos = self._mixed[key] & mask
            while table[pos] is not None:
                pos = (pos + 1) & mask
            table[pos] = key
        self.n, self.table, self.max_fill = new_n, table, max_fill(new_n, self.f)

    def keys(self) -> list[str]:
        """The key set's spliterator order (``keySet().stream()``): slot 0 upwards."""
        return [key for key in self.table if key is not None]


def resource_location_hash(rid: str) -> int:
    """ResourceLocation.hashCode: 31 * namespace.hashCode() + path.hashCode() (unsigned 32-bit)."""
    namespace, _, path = rid.partition(":")
    return (31 * java_string_hash(namespace) + java_string_hash(path)) & 0xFFFFFFFF


def java_hash_map_order(keys: list, hash_code) -> list:
    """java.util.HashMap's iteration order of ``keys`` put in that order into a ``new HashMap<>()``
    (16 buckets, doubled whenever the size passes three quarters of them: HashMap.putVal/resize):
    bucket by bucket (the hash spread ``h ^ h >>> 16``, masked), each bucket in insertion order,
    which resize's split keeps. A bucket of 8 or more keys becomes a tree whose links may reorder
    it; with the few thousand keys of a recipe map that is all but impossible, and not reproduced."""
    capacity = 16
    while len(keys) > capacity * 3 // 4:
        capacity *= 2

    def bucket(key) -> int:
        h = hash_code(key) & 0xFFFFFFFF
        return (h ^ (h >> 16)) & (capacity - 1)
    return sorted(keys, key=bucket)  # stable: insertion order within a bucket
