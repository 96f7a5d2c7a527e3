"""java.util.Random and Collections.shuffle, as sort=random and @r draw from them, pinned to
values printed by OpenJDK 17 (java/util/Random.java: setSeed, next, nextInt(bound);
java/util/Collections.java: shuffle)."""
from __future__ import annotations

import numpy as np

from emulator.world import java_random


def _state(seed: int) -> np.ndarray:
    state = np.zeros(1, dtype=np.int64)
    java_random.set_seed(state, seed)
    return state


def test_next_int_of_bounds_matches_java():
    # new Random(42).nextInt(b) for each b in turn: powers of two take the high bits, bounds just
    # past a power of two reject draws whose int sum overflows
    state = _state(42)
    bounds = [10, 100, 7, 2, 3, 1000000007, 1 << 30, 5, 1073741825, 2147483647]
    assert [java_random.next_int(state, b) for b in bounds] == [
        0, 63, 6, 0, 0, 595021505, 759898459, 4, 196118093, 1939977182]


def test_next_32_bits_match_java():
    assert java_random.next_bits(_state(0), 32) - (1 << 32) == -1155484576  # new Random(0).nextInt()


def test_shuffle_matches_collections_shuffle():
    # Collections.shuffle(list of 0..9, new Random(7))
    items = list(range(10))
    java_random.shuffle(_state(7), items, 0, len(items))
    assert items == [0, 1, 9, 3, 7, 4, 8, 5, 2, 6]
    window = np.arange(14)  # a slice of an array, as the VM shuffles what a selector found
    java_random.shuffle(_state(7), window, 2, 10)
    assert window.tolist() == [0, 1] + [v + 2 for v in items] + [12, 13]
