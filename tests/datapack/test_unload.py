"""pool:unload removes what the pack made: after a table and a shot nothing of the pack is left
in the world (no objective or score, no entity of the pack, no storage, no scheduled function),
and loading the pack again plays a shot as in a fresh world."""
import re

import pytest

from poolgame.shot import BREAK, TABLE_CORNER, new_table, play, strike
from tests.datapack.pack_paths import PACK
from tests.datapack.pool_world import BACKENDS

FUNCTIONS = PACK / "data" / "pool" / "function"


def objectives(emu):
    scoreboard = emu.state.scoreboard
    return [name for name in scoreboard.objectives if scoreboard.exists(name)]


def assert_nothing_of_the_pack(emu):
    assert objectives(emu) == [] and emu.scores() == {}
    # the only entity left is the player watching the table, without any tag of the pack
    assert [(e["type"], e["tags"]) for e in emu.entities("@e")] == [("minecraft:player", [])]
    assert emu.entities("@e[tag=pool.ball]") == []
    assert emu.state.storage == {}
    assert emu.state.schedule.pending() == []


def test_unload_removes_the_objectives_load_creates():
    created = re.findall(r"^scoreboard objectives add (\S+)", (FUNCTIONS / "load.mcfunction").read_text(), re.M)
    removed = re.findall(r"^scoreboard objectives remove (\S+)", (FUNCTIONS / "unload.mcfunction").read_text(), re.M)
    assert created and sorted(removed) == sorted(created)


@pytest.mark.parametrize("backend", BACKENDS)
def test_nothing_of_the_pack_remains_after_a_shot(backend):
    emu = new_table(backend=backend, sanitize=True)
    assert strike(emu, BREAK) == []
    emu.tick(10)                                     # mid-break: balls moving, a physics tick carried over
    assert any(name.startswith("pool.") for name in objectives(emu))
    emu.call("pool:unload")
    assert not emu.overflows and not emu.diagnostics
    assert_nothing_of_the_pack(emu)
    # still enabled, the pack's tick fails on the missing objectives and changes nothing
    emu.tick()
    assert_nothing_of_the_pack(emu)
    assert {d.message.split("'")[1] for d in emu.diagnostics} == {"pool.game", "pool.power"}


def test_loaded_again_the_pack_plays_as_in_a_fresh_world():
    fresh = play(new_table(sanitize=True), BREAK)
    emu = new_table(sanitize=True)
    strike(emu, BREAK)
    emu.tick(10)
    emu.call("pool:unload")
    emu.call("#minecraft:load")                      # /reload
    emu.call("pool:table/setup", at=TABLE_CORNER)
    again = play(emu, BREAK)
    assert again.at_rest and not again.overflows and not again.diagnostics
    assert again.balls == fresh.balls
    assert again.commands_per_tick == fresh.commands_per_tick
