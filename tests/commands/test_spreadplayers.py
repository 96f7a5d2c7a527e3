"""``spreadplayers`` on both backends, as SpreadPlayersCommand does it (decompiled 1.21,
server/commands/SpreadPlayersCommand.java): positions within the square centre +- max range, no two
closer than the spread distance once settled (each put at its column's block centre), on the first
non-air block under ``max_height`` with two air blocks over it; unsafe columns (liquid, fire, none
under the maximum) drawn again, and 10,000 unsettled rounds fail with the game's message; teams of
players share a position. The columns are the emulator's seeded draws (the game's random is unseeded)."""
import itertools
import math

import pytest

from emulator.world import spreading
from emulator.world.errors import CommandFailure
from tests.world.world_emulator import emulator

FLOOR = "fill -20 63 -20 20 63 20 stone\n"
MARKERS = 'summon marker 0 80 0 {Tags:["a"]}\n' * 4


def positions(emu, selector="@e[tag=a]"):
    return [tuple(e["pos"]) for e in emu.entities(selector)]


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_entities_land_apart_on_the_floor_within_range(tmp_path, backend):
    emu = emulator(tmp_path, backend, {"t:go": FLOOR + MARKERS +
                                       "execute store result score #n o run spreadplayers 0 0 6 12 false @e[tag=a]"})
    emu.call("t:go")
    assert emu.score("#n", "o") == 4
    found = positions(emu)
    assert len(found) == 4
    for x, y, z in found:
        assert y == 64.0 and x % 1 == 0.5 and z % 1 == 0.5  # block centres, on top of the stone
        assert -12.5 <= x <= 12.5 and -12.5 <= z <= 12.5  # the square 0.5 +- 12 (an integer centre is centred)
    for a, b in itertools.combinations(found, 2):  # settled >= 6 apart, then floored to block centres
        assert math.dist((a[0], a[2]), (b[0], b[2])) > 6 - math.sqrt(2)


def test_both_backends_draw_the_same_columns(tmp_path):
    found = []
    for backend in ("numba", "python"):
        emu = emulator(tmp_path / backend, backend, {"t:go": FLOOR + MARKERS + "spreadplayers 0 0 3 8 false @e[tag=a]"})
        emu.call("t:go")
        found.append(positions(emu))
    assert found[0] == found[1]


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_under_caps_the_height_searched(tmp_path, backend):
    roof = "fill -20 70 -20 20 70 20 glass\n"
    emu = emulator(tmp_path, backend, {"t:low": FLOOR + roof + MARKERS + "spreadplayers 0 0 1 5 false @e[tag=a]",
                                       "t:under": "spreadplayers 0 0 1 5 under 68 false @e[tag=a]"})
    emu.call("t:low")
    assert {p[1] for p in positions(emu)} == {71.0}  # on the roof: the first block down from the top
    emu.call("t:under")
    assert {p[1] for p in positions(emu)} == {64.0}  # the roof is over the maximum: the floor


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_no_safe_column_fails_after_ten_thousand_rounds(tmp_path, backend):
    water = "fill -20 63 -20 20 63 20 water\n"
    emu = emulator(tmp_path, backend, {"t:void": MARKERS + "execute store success score #void o run "
                                                           "spreadplayers 0 0 2 4 false @e[tag=a]",
                                       "t:water": water + "execute store success score #water o run "
                                                          "spreadplayers 0 0 2 4 false @e[tag=a]"})
    emu.call("t:void")
    emu.call("t:water")
    assert (emu.score("#void", "o"), emu.score("#water", "o")) == (0, 0)
    assert {p[1] for p in positions(emu)} == {80.0}  # nobody moved


def test_the_failures_say_what_the_game_says(tmp_path):
    emu = emulator(tmp_path, "python", {"t:go": 'summon marker 0 80 0 {Tags:["a"]}'})
    emu.call("t:go")
    state, found = emu.state, emu.state.entities.entities
    with pytest.raises(CommandFailure) as failed:
        spreading.spread(state, found, (100.5, 100.5), 2.0, 4.0, 320, False, "minecraft:overworld")
    assert failed.value.message == ("Could not spread 1 entity/entities around 100.5, 100.5 (too many entities for "
                                    "space - try using spread of at most 0.00)")
    with pytest.raises(CommandFailure) as failed:
        spreading.spread(state, found, (0.5, 0.5), 2.0, 4.0, -100, False, "minecraft:overworld")
    assert failed.value.message == "Invalid maxHeight -100; expected higher than world minimum -64"


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_players_of_a_team_share_a_position(tmp_path, backend):
    emu = emulator(tmp_path, backend, {
        "t:teams": "team add red\nteam join red Alex\nteam join red Steve\n" + FLOOR +
                   'summon marker 0 80 0 {Tags:["a"]}\n'
                   "execute store result score #n o run spreadplayers 0 0 4 10 true @a\n"
                   "execute store result score #m o run spreadplayers 0 0 4 10 true @e[tag=a]"})
    emu.add_player("Alex", (0, 80, 0))
    emu.add_player("Steve", (0, 80, 0))
    emu.add_player("Sam", (0, 80, 0))
    emu.call("t:teams")
    assert (emu.score("#n", "o"), emu.score("#m", "o")) == (2, 1)  # red and no team; the marker alone
    alex, steve, sam = (positions(emu, f"@a[name={name}]")[0] for name in ("Alex", "Steve", "Sam"))
    assert alex == steve and alex != sam
