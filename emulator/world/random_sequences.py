"""The game's random sources for ``random value|roll|reset``: Xoroshiro128++ seeded as
RandomSequences does, so a named sequence gives the game's exact numbers for a given world seed.

Source (decompiled 1.21): world/RandomSequences.java (createSequence: seed = (includeWorldSeed ?
worldSeed : 0) ^ salt), world/RandomSequence.java (upgradeSeedTo128bitUnmixed, xor with the MD5 of
the id, mixed), world/level/levelgen/RandomSupport.java, XoroshiroRandomSource.java (nextInt(bound)),
Xoroshiro128PlusPlus.java (nextLong), util/Mth.randomBetweenInclusive.

Without a sequence the game draws from the level's own random (seeded from the clock, so no two
runs agree); the emulator draws from a Xoroshiro source seeded with the world seed instead, which
keeps runs reproducible.
"""
from __future__ import annotations

import hashlib

_MASK64 = (1 << 64) - 1
GOLDEN_RATIO_64 = 0x9E3779B97F4A7C15
SILVER_RATIO_64 = 0x6A09E667F3BCC909


def _rotl(x: int, k: int) -> int:
    return ((x << k) | (x >> (64 - k))) & _MASK64


def mix_stafford13(z: int) -> int:
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & _MASK64
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & _MASK64
    return z ^ (z >> 31)


def seed_from_hash_of(text: str) -> tuple[int, int]:
    """RandomSupport.seedFromHashOf: the MD5 digest as two big-endian longs."""
    digest = hashlib.md5(text.encode("utf-8")).digest()
    return int.from_bytes(digest[:8], "big"), int.from_bytes(digest[8:], "big")


class Xoroshiro:
    """XoroshiroRandomSource over Xoroshiro128PlusPlus (state as unsigned 64-bit ints)."""

    def __init__(self, lo: int, hi: int) -> None:
        if (lo | hi) == 0:
            lo, hi = GOLDEN_RATIO_64, SILVER_RATIO_64
        self.lo, self.hi = lo, hi

    @classmethod
    def from_seed(cls, seed: int) -> "Xoroshiro":
        """``new XoroshiroRandomSource(long)``: the seed upgraded to 128 bits and mixed."""
        lo = (seed ^ SILVER_RATIO_64) & _MASK64
        hi = (lo + GOLDEN_RATIO_64) & _MASK64
        return cls(mix_stafford13(lo), mix_stafford13(hi))

    @classmethod
    def sequence(cls, seed: int, sequence_id: str | None) -> "Xoroshiro":
        """RandomSequence.createSequence: unmixed upgrade, xor the id's MD5 seed, then mix."""
        lo = (seed ^ SILVER_RATIO_64) & _MASK64
        hi = (lo + GOLDEN_RATIO_64) & _MASK64
        if sequence_id is not None:
            key_lo, key_hi = seed_from_hash_of(sequence_id)
            lo, hi = lo ^ key_lo, hi ^ key_hi
        return cls(mix_stafford13(lo), mix_stafford13(hi))

    def next_long(self) -> int:
        """The next value as an unsigned 64-bit int."""
        lo, hi = self.lo, self.hi
        out = (_rotl((lo + hi) & _MASK64, 17) + lo) & _MASK64
        hi ^= lo
        self.lo = _rotl(lo, 49) ^ hi ^ ((hi << 21) & _MASK64)
        self.hi = _rotl(hi, 28)
        return out

    def next_int_bounded(self, bound: int) -> int:
        """XoroshiroRandomSource.nextInt(bound) (Lemire's method, as the game writes it)."""
        product = (self.next_long() & 0xFFFFFFFF) * bound
        if (product & 0xFFFFFFFF) < bound:
            threshold = (-bound & 0xFFFFFFFF) % bound  # Integer.remainderUnsigned(~bound + 1, bound)
            while (product & 0xFFFFFFFF) < threshold:
                product = (self.next_long() & 0xFFFFFFFF) * bound
        return product >> 32

    def between_inclusive(self, low: int, high: int) -> int:
        """Mth.randomBetweenInclusive."""
        return self.next_int_bounded(high - low + 1) + low


def _java_long(value: int) -> int:
    return value & _MASK64


class RandomSequences:
    """RandomSequences: named sources created on first use from the world seed and the defaults
    (``salt``, include world seed, include sequence id) that ``random reset * SEED ...`` sets."""

    def __init__(self, world_seed: int = 0) -> None:
        self.world_seed = world_seed
        self.salt = 0
        self.include_world_seed = True
        self.include_sequence_id = True
        self.sequences: dict[str, Xoroshiro] = {}
        self.level_random = Xoroshiro.from_seed(world_seed)

    def _create(self, sequence_id: str, salt: int, include_world_seed: bool, include_sequence_id: bool) -> Xoroshiro:
        seed = _java_long((self.world_seed if include_world_seed else 0) ^ salt)
        return Xoroshiro.sequence(seed, sequence_id if include_sequence_id else None)

    def get(self, sequence_id: str) -> Xoroshiro:
        source = self.sequences.get(sequence_id)
        if source is None:
            source = self.sequences[sequence_id] = self._create(
                sequence_id, self.salt, self.include_world_seed, self.include_sequence_id)
        return source

    def reset(self, sequence_id: str, salt: int | None = None, include_world_seed: bool = True,
              include_sequence_id: bool = True) -> None:
        """``random reset ID [SEED [W S]]``: a fresh source, with the defaults when no seed is given."""
        if salt is None:
            salt, include_world_seed, include_sequence_id = self.salt, self.include_world_seed, self.include_sequence_id
        self.sequences[sequence_id] = self._create(sequence_id, salt, include_world_seed, include_sequence_id)

    def clear(self) -> int:
        """``random reset *``: forget every sequence; the count of those forgotten."""
        count = len(self.sequences)
        self.sequences.clear()
        return count
