"""``java.util.Random`` over a state both backends share, and ``Collections.shuffle``: what
``sort=random`` and ``@r`` draw from.

The game shuffles with ``Collections.shuffle(list)`` (EntitySelectorParser.ORDER_RANDOM), whose
``Random`` is unseeded; the emulator seeds it (:class:`emulator.world.entities.EntityStore`), so a
run repeats. The state is one int64 in an array (``EntityTable.random``): Python's selectors and
the numba VM's (which compiles these same functions) advance it in place, so their picks agree.

Sources: OpenJDK 17 java/util/Random.java (setSeed's scramble, next, nextInt(bound)) and
java/util/Collections.java (shuffle: ``for (i = size; i > 1; i--) swap(list, i - 1, rnd.nextInt(i))``).
The arithmetic keeps to int64 (the products wrap, their low 48 bits exact), so numba runs it as written.
"""
from __future__ import annotations

MULTIPLIER = 0x5DEECE66D
MASK = (1 << 48) - 1


def set_seed(state, seed: int) -> None:
    """``Random.setSeed``: the seed scrambled with the multiplier, 48 bits kept."""
    state[0] = (int(seed) ^ MULTIPLIER) & MASK


def next_bits(state, bits: int) -> int:
    """``Random.next(bits)``: the next 48-bit seed, its top ``bits`` bits (bits <= 31: never negative)."""
    seed = (int(state[0]) * MULTIPLIER + 0xB) & MASK
    state[0] = seed
    return seed >> (48 - bits)


def next_int(state, bound: int) -> int:
    """``Random.nextInt(bound)`` (bound > 0): a power of two takes the high bits; otherwise draws
    again while ``u - r + (bound - 1)`` overflows an int."""
    r = next_bits(state, 31)
    m = bound - 1
    if bound & m == 0:
        return (bound * r) >> 31
    u = r
    r = u % bound
    while (u - r + m) > 0x7FFFFFFF:  # Java's int sum wraps below 0
        u = next_bits(state, 31)
        r = u % bound
    return r


def shuffle(state, items, first: int, count: int) -> None:
    """``Collections.shuffle`` of ``items[first:first + count]`` in place (a list or an array)."""
    for i in range(count, 1, -1):
        j = next_int(state, i)
        a, b = first + i - 1, first + j
        items[a], items[b] = items[b], items[a]
