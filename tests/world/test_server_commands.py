"""``time``, ``random``, ``trigger`` and ``scoreboard players enable`` on both backends.

Sources (decompiled 1.21): server/commands/TimeCommand.java, server/level/ServerLevel.tickTime,
server/commands/RandomCommand.java (randomSample), world/RandomSequences.java,
world/RandomSequence.java, world/level/levelgen/RandomSupport.java, XoroshiroRandomSource.java,
Xoroshiro128PlusPlus.java, server/commands/TriggerCommand.java (getScore),
server/commands/ScoreboardCommand.java (enableTrigger).
"""
from __future__ import annotations

import pytest

from emulator.world.random_sequences import RandomSequences, Xoroshiro, mix_stafford13, seed_from_hash_of
from tests.world.world_emulator import emulator

BACKENDS = ["python", "numba"]


# ---------------------------------------------------------------------- time
@pytest.mark.parametrize("backend", BACKENDS)
def test_time_set_add_query(tmp_path, backend):
    emu = emulator(tmp_path, backend, {"t:main": "\n".join([
        # TimeCommand.setTime/addTime return getDayTime() = (int)(dayTime % 24000)
        "execute store result score #set o run time set 30000",
        "execute store result score #add o run time add 20000",
        "execute store result score #daytime o run time query daytime",
        # (int)(dayTime / 24000 % Integer.MAX_VALUE): 50000 / 24000 = 2
        "execute store result score #day o run time query day",
        "execute store result score #night o run time set night",
        "execute store result score #gametime o run time query gametime",
    ])})
    emu.call("t:main")
    assert [emu.score(h, "o") for h in ("#set", "#add", "#daytime", "#day", "#night", "#gametime")] == \
        [6000, 2000, 2000, 2, 13000, 0]


@pytest.mark.parametrize("backend", BACKENDS)
def test_tick_advances_gametime_and_daytime_unless_daylight_cycle_is_off(tmp_path, backend):
    # ServerLevel.tickTime: gameTime + 1, scheduled events, then dayTime + 1 if RULE_DAYLIGHT
    emu = emulator(tmp_path, backend, {
        "t:q": "execute store result score #g o run time query gametime\n"
               "execute store result score #d o run time query daytime",
        "t:off": "gamerule doDaylightCycle false",
    })
    emu.tick(5)
    emu.call("t:q")
    assert (emu.score("#g", "o"), emu.score("#d", "o")) == (5, 5)
    emu.call("t:off")
    emu.tick(3)
    emu.call("t:q")
    assert (emu.score("#g", "o"), emu.score("#d", "o")) == (8, 5)


# ---------------------------------------------------------------------- random
def test_mix_stafford13_is_splitmix64s_finaliser():
    # RandomSupport.mixStafford13 is SplitMix64's mix: its first output for state 0 is
    # mix(0x9E3779B97F4A7C15) = 0xE220A8397B1DCDAF (Vigna, splitmix64.c)
    assert mix_stafford13(0x9E3779B97F4A7C15) == 0xE220A8397B1DCDAF


def test_xoroshiro128pp_steps_by_hand():
    # Xoroshiro128PlusPlus.nextLong from (lo, hi) = (1, 0): out = rotl(1 + 0, 17) + 1;
    # hi ^= lo -> 1; lo = rotl(1, 49) ^ 1 ^ (1 << 21); hi = rotl(1, 28)
    rng = Xoroshiro(1, 0)
    assert rng.next_long() == (1 << 17) + 1
    lo, hi = (1 << 49) ^ 1 ^ (1 << 21), 1 << 28
    assert (rng.lo, rng.hi) == (lo, hi)
    total = (lo + hi) & (2**64 - 1)
    assert rng.next_long() == ((((total << 17) | (total >> 47)) & (2**64 - 1)) + lo) & (2**64 - 1)


def test_all_zero_state_is_replaced():
    # Xoroshiro128PlusPlus: (0, 0) becomes (GOLDEN_RATIO_64, SILVER_RATIO_64)
    assert (Xoroshiro(0, 0).lo, Xoroshiro(0, 0).hi) == (0x9E3779B97F4A7C15, 0x6A09E667F3BCC909)


def test_sequence_seed_xors_the_md5_of_the_id():
    # RandomSequence.createSequence: upgradeSeedTo128bitUnmixed(seed) xor seedFromHashOf(id), mixed
    lo = 5 ^ 0x6A09E667F3BCC909
    hi = (lo + 0x9E3779B97F4A7C15) & (2**64 - 1)
    key_lo, key_hi = seed_from_hash_of("t:dice")
    rng = Xoroshiro.sequence(5, "t:dice")
    assert (rng.lo, rng.hi) == (mix_stafford13(lo ^ key_lo), mix_stafford13(hi ^ key_hi))


def test_bounded_int_uses_the_high_half_of_the_product():
    # XoroshiroRandomSource.nextInt(bound) = (unsigned low 32 bits of nextLong * bound) >> 32
    reference = Xoroshiro(1, 0)
    first = reference.next_long() & 0xFFFFFFFF
    assert Xoroshiro(1, 0).next_int_bounded(6) == (first * 6) >> 32


@pytest.mark.parametrize("backend", BACKENDS)
def test_random_value_from_a_sequence_is_reproducible_and_reset(tmp_path, backend):
    emu = emulator(tmp_path, backend, {
        "t:roll": "execute store result score #a o run random value 1..6 t:dice\n"
                  "execute store result score #b o run random value 1..6 t:dice",
        "t:reset": "random reset t:dice",
    })
    expected = RandomSequences(0).get("t:dice")
    first, second = expected.between_inclusive(1, 6), expected.between_inclusive(1, 6)
    emu.call("t:roll")
    assert (emu.score("#a", "o"), emu.score("#b", "o")) == (first, second)
    emu.call("t:reset")
    emu.call("t:roll")
    assert (emu.score("#a", "o"), emu.score("#b", "o")) == (first, second)


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("command, ok", [
    ("random value 5..5", False),               # span 0: "range_too_small"
    ("random value ..0", False),                # MIN..0: span 2^31 >= 2^31-1
    ("random value 0..2147483647", False),      # span exactly Integer.MAX_VALUE is refused
    ("random value 0..2147483646", True),       # span 2147483646: the widest allowed
    ("random value -5..-2", True),
])
def test_random_range_limits(tmp_path, backend, command, ok):
    emu = emulator(tmp_path, backend, {"t:main": f"execute store success score #ok o run {command}"})
    emu.call("t:main")
    assert emu.score("#ok", "o") == int(ok)


@pytest.mark.parametrize("backend", BACKENDS)
def test_random_roll_broadcasts_its_result(tmp_path, backend):
    emu = emulator(tmp_path, backend, {"t:main": "execute store result score #r o run random roll 1..100 t:d"})
    emu.call("t:main")
    value = RandomSequences(0).get("t:d").between_inclusive(1, 100)
    assert emu.score("#r", "o") == value
    # commands.random.roll: "%s rolled %s (from %s to %s)", the source's display name
    assert [(e.kind, e.text) for e in emu.log] == [("chat", f"Server rolled {value} (from 1 to 100)")]


@pytest.mark.parametrize("backend", BACKENDS)
def test_random_reset_all_counts_sequences(tmp_path, backend):
    emu = emulator(tmp_path, backend, {"t:main": "random value 1..2 t:a\nrandom value 1..2 t:b\n"
                                       "execute store result score #n o run random reset *"})
    emu.call("t:main")
    assert emu.score("#n", "o") == 2


# ---------------------------------------------------------------------- trigger
@pytest.mark.parametrize("backend", BACKENDS)
def test_trigger_needs_enable_and_locks_again(tmp_path, backend):
    emu = emulator(tmp_path, backend, {
        "t:init": "scoreboard objectives add t trigger",
        "t:press": "execute store success score #ok o run trigger t add 5",
        "t:enable": "execute store result score #en o run scoreboard players enable @a t",
    })
    emu.call("t:init")
    emu.add_player("Alex")
    emu.call("t:press", as_="Alex")
    assert (emu.score("#ok", "o"), emu.score("Alex", "t")) == (0, None)  # no score: not primed
    emu.call("t:enable")
    assert (emu.score("#en", "o"), emu.score("Alex", "t")) == (1, 0)
    emu.call("t:enable")  # already unlocked: nothing changed, the command fails
    assert emu.score("#en", "o") == 0
    emu.call("t:press", as_="Alex")
    assert (emu.score("#ok", "o"), emu.score("Alex", "t")) == (1, 5)
    emu.call("t:press", as_="Alex")  # locked again by the first use
    assert (emu.score("#ok", "o"), emu.score("Alex", "t")) == (0, 5)


@pytest.mark.parametrize("backend", BACKENDS)
def test_trigger_refuses_non_trigger_objectives_and_non_players(tmp_path, backend):
    emu = emulator(tmp_path, backend, {
        "t:init": "scoreboard objectives add t trigger\nscoreboard players enable @a t",
        "t:dummy": "execute store success score #ok o run trigger o",
        "t:set": "execute store result score #v o run trigger t set -3",
    })
    emu.add_player("Alex")
    emu.call("t:init")
    emu.call("t:dummy", as_="Alex")
    assert emu.score("#ok", "o") == 0
    emu.call("t:set")  # run by the server: a player is required
    assert emu.score("#v", "o") == 0 and emu.score("Alex", "t") == 0
    emu.call("t:set", as_="Alex")
    assert emu.score("#v", "o") == -3 and emu.score("Alex", "t") == -3


@pytest.mark.parametrize("backend", BACKENDS)
def test_random_reset_with_a_seed_and_flags(tmp_path, backend):
    # RandomSequences.createSequence: seed = (includeWorldSeed ? worldSeed : 0) ^ salt, the id's
    # hash mixed in only with includeSequenceId; `random reset * SALT ...` sets the defaults
    emu = emulator(tmp_path, backend, {
        "t:a": "random reset t:d 7 false false\nexecute store result score #a o run random value 1..1000 t:d",
        "t:b": "random reset * 9 true false\nexecute store result score #b o run random value 1..1000 t:e",
    })
    emu.call("t:a")
    emu.call("t:b")
    assert emu.score("#a", "o") == Xoroshiro.sequence(7, None).between_inclusive(1, 1000)
    assert emu.score("#b", "o") == Xoroshiro.sequence(0 ^ 9, None).between_inclusive(1, 1000)
