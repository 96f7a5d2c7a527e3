"""The order in which ``*`` visits score holders: the game's fastutil hash map, replayed.

Sources: decompiled 1.21 world/scores/Scoreboard.java (playerScores = new
Object2ObjectOpenHashMap<>(16, 0.5F); getTrackedPlayers streams keySet(); resetSinglePlayerScore
drops a holder with no score left; removeObjective keeps the holders); fastutil 8.5
Object2ObjectOpenHashMap (find/insert: linear probing from mix(hashCode) & mask; insert grows to
arraySize(size + 1) when the old size >= maxFill; removeEntry: shiftKeys, then shrinks to n / 2 when
n > minN && size < maxFill / 4 && n > 16; rehash takes keys from the top slot down; KeySpliterator
walks slots 0 .. n-1, unlike the iterator and forEach, which walk down) and HashCommon
(mix(x) = h ^ h >>> 16 with h = x * 0x9E3779B9; arraySize; maxFill); java.lang.String.hashCode.
The expected orders below were worked out by hand from that code.
"""
from __future__ import annotations

import pytest
from hypothesis import given, settings, strategies as st

from emulator.world.state import Scoreboard
from emulator.world.hash_order import OpenHashKeys, array_size, java_string_hash, max_fill, mix
from tests.world.world_emulator import emulator

# mix(String.hashCode) & 31 of the keys used here, worked out from the formulas above
SLOTS32 = {"#x": 18, "#c": 18, "#f": 18, "#d": 19, "#af": 31, "#ah": 31, "#oa": 0}


def test_string_hash_code():
    assert java_string_hash("") == 0
    assert java_string_hash("#a") == 35 * 31 + 97  # s[0]*31 + s[1]
    assert java_string_hash("hello") == 99162322  # the value Java gives
    assert java_string_hash("é") == 0xE9  # UTF-16 code units, not UTF-8 bytes


def test_mix_by_hand():
    # 1182 * 0x9E3779B9 mod 2^32 = 0x8424042E; ^ (>>> 16 = 0x8424) = 0x8424800A; & 31 = 10
    assert mix(1182) == 0x8424800A


def test_table_sizes():
    # (16, 0.5F): n = nextPowerOfTwo(ceil(16 / 0.5)) = 32, maxFill = min(ceil(32 * 0.5), 31) = 16
    assert (array_size(16, 0.5), max_fill(32, 0.5)) == (32, 16)
    assert array_size(18, 0.5) == 64  # the growth after the 17th key: arraySize(size + 1)


@pytest.mark.parametrize("key, slot", sorted(SLOTS32.items()))
def test_slots_used_below(key, slot):
    assert mix(java_string_hash(key)) & 31 == slot


def keys_after(inserted, removed=()):
    table = OpenHashKeys(16, 0.5)
    for key in inserted:
        table.add(key)
    for key in removed:
        table.remove(key)
    return table


def test_collisions_take_the_next_free_slot_and_iterate_upwards():
    # #x, #c, #f all hash to 18: slots 18, 19, 20; #d (19) probes to 21
    assert keys_after(["#x", "#c", "#f", "#d"]).keys() == ["#x", "#c", "#f", "#d"]
    # the same keys in another order: #d takes 19 first, so #c goes to 20 and #f to 21
    assert keys_after(["#d", "#x", "#c", "#f"]).keys() == ["#x", "#d", "#c", "#f"]


def test_removal_shifts_the_cluster_back():
    # remove #x (18): #c (home 18) moves to 18, #f (18) to 19, #d (19) to 20
    table = keys_after(["#x", "#c", "#f", "#d"], ["#x"])
    assert table.keys() == ["#c", "#f", "#d"]
    table.add("#x")  # back at the end of the cluster: slot 21
    assert table.keys() == ["#c", "#f", "#d", "#x"]


def test_probing_and_shifting_wrap_around():
    # #af at 31, #ah (31) wraps to 0, #oa (0) goes to 1: iteration from slot 0
    assert keys_after(["#af", "#ah", "#oa"]).keys() == ["#ah", "#oa", "#af"]
    # removing #af: shiftKeys' last > pos branch moves #ah back to 31, then #oa to 0
    assert keys_after(["#af", "#ah", "#oa"], ["#af"]).keys() == ["#oa", "#ah"]


# 17 keys with distinct slots in a 64-slot table (mix(hashCode) & 63)
SLOTS64 = {"pa": 14, "pb": 61, "pc": 13, "pd": 26, "pe": 8, "pf": 59, "pg": 11, "ph": 20, "pi": 18,
           "pj": 49, "pl": 22, "pn": 55, "pp": 40, "pq": 38, "pr": 37, "pt": 34, "pu": 32}


def test_growth_and_shrink():
    assert all(mix(java_string_hash(k)) & 63 == s for k, s in SLOTS64.items())
    keys = list(SLOTS64)
    table = keys_after(keys[:16])
    assert table.n == 32  # 16 keys fit: the check is on the size before the insert
    table.add(keys[16])
    assert table.n == 64
    assert table.keys() == sorted(keys, key=SLOTS64.get)
    for key in keys[:9]:  # 8 left: not yet below maxFill / 4 = 8
        table.remove(key)
    assert table.n == 64
    table.remove(keys[9])  # 7 < 8: back to 32 slots
    assert table.n == 32
    assert table.keys() == sorted(keys[10:], key=lambda k: (mix(java_string_hash(k)) & 31, k != "pq"))


def test_scoreboard_order_follows_the_map():
    board = Scoreboard()
    board.add_objective("o")
    board.add_objective("p")
    for name in ["#d", "#x", "#c", "#f"]:
        board.set(name, "o", 1)
    assert board.tracked_holders() == ["#x", "#d", "#c", "#f"]
    board.set("#x", "p", 1)
    board.reset("#x", "o")  # still has a score in p: stays
    assert board.tracked_holders() == ["#x", "#d", "#c", "#f"]
    # no score left: leaves the map. shiftKeys(18): #d (home 19) stays, #c (home 18) moves into
    # 18, #f (home 18) into 20
    board.reset("#x", "p")
    assert board.tracked_holders() == ["#c", "#d", "#f"]


def test_removed_objective_keeps_its_holders_tracked():
    board = Scoreboard()
    board.add_objective("o")
    board.set("#a", "o", 1)
    board.remove_objective("o")
    assert board.tracked_holders() == ["#a"]  # an empty PlayerScores stays in the map
    board.add_objective("o")
    board.reset("#a", "o")  # resetSinglePlayerScore: no scores -> removed
    assert board.tracked_holders() == []


@pytest.mark.parametrize("backend", ["python", "numba"])
def test_wildcard_operation_visits_holders_in_map_order(tmp_path, backend):
    # operation * o += * o: for each target in order, add every source in order. With #d = 1 and
    # #x = 10 the map order is #x (slot 18), #d (19): #x = 10 + 10 + 1 = 21, then
    # #d = (1 + 21) + 22 = 44. (Interning order, #d first, would give #d = 12, #x = 44.)
    emu = emulator(tmp_path, backend, {"t:main": "scoreboard players set #d o 1\nscoreboard players set #x o 10\n"
                                       "scoreboard players operation * o += * o"})
    emu.call("t:main")
    assert (emu.score("#x", "o"), emu.score("#d", "o")) == (21, 44)


# Linear probing's invariant after any history (fastutil relies on it to find keys): between a
# key's home slot and its slot there is no empty slot; and the table holds exactly the live keys.
_NAMES = st.sampled_from([f"#{a}{b}" for a in "abcdefgh" for b in "abcdefgh"])


@settings(max_examples=200, deadline=None)
@given(st.lists(st.tuples(st.booleans(), _NAMES), max_size=120))
def test_probing_invariant_holds_after_any_history(operations):
    table, live = OpenHashKeys(16, 0.5), set()
    for add, key in operations:
        (table.add if add else table.remove)(key)
        (live.add if add else live.discard)(key)
    assert sorted(table.keys()) == sorted(live) and len(table) == len(live)
    mask = table.n - 1
    for pos, key in enumerate(table.table):
        if key is None:
            continue
        slot = mix(java_string_hash(key)) & mask
        while slot != pos:
            assert table.table[slot] is not None, (key, slot, pos)
            slot = (slot + 1) & mask
    assert table.n == 32 or len(table) >= table.max_fill // 4  # shrinks back, never below 32
