"""The Emulator API: load, call, tick, run_until, scores, log, profile, diagnostics, backends."""
from __future__ import annotations

import pytest

from emulator import Emulator
from vm_helpers import SETUP, emulator_for

FUNCTIONS = {
    "t:load": SETUP + "scoreboard players set #n o 0",
    "t:tick": "scoreboard players add #n o 1\nfunction t:work",
    "t:work": "scoreboard players operation #sq o = #n o\nscoreboard players operation #sq o *= #n o\n"
              "execute if score #n o matches 2 run say two",
    "t:answer": "return 42",
}
TAGS = {"minecraft:load": ["t:load"], "minecraft:tick": ["t:tick"]}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_tick_scores_log(tmp_path, backend):
    emu = emulator_for(tmp_path, FUNCTIONS, TAGS, backend=backend)
    assert emu.tick(3) == sum(emu.commands_per_tick)
    assert emu.score("#sq", "o") == 9
    assert emu.score("#nobody", "o") is None
    assert emu.scores() == {"o": {"#n": 3, "#sq": 9}}
    assert [(e.tick, e.kind, e.text) for e in emu.log] == [(1, "say", "[Server] two")]
    assert emu.call("t:answer") == 42


def test_run_until(tmp_path):
    emu = emulator_for(tmp_path, FUNCTIONS, TAGS)
    ran = emu.run_until(lambda e: e.score("#n", "o") == 5, max_ticks=100)
    assert ran == 5 and emu.ticks == 5
    assert emu.run_until(lambda e: False, max_ticks=3) == 3


def test_set_score_and_call(tmp_path):
    emu = emulator_for(tmp_path, FUNCTIONS, TAGS)
    emu.set_score("#n", "o", 6)
    emu.call("t:work")
    assert emu.score("#sq", "o") == 36
    with pytest.raises(ValueError):
        emu.set_score("#n", "o", 2**31)


def test_profile_per_line_and_function(tmp_path):
    emu = emulator_for(tmp_path, FUNCTIONS, TAGS)
    emu.tick(4)
    profile = emu.profile
    work = {line: c for (path, line), c in profile.lines.items() if path.endswith("work.mcfunction")}
    assert work == {1: 4, 2: 4, 3: 4 + 1}  # the if stage each tick, `say` once
    assert profile.functions_self["t:work"] == 13
    # per tick: its add and its call of t:work (2), t:work's 3 lines; `say` once
    assert profile.functions_total["t:tick"] == 4 * (2 + 3) + 1
    assert profile.ticks == emu.commands_per_tick


def test_call_tag_and_default_namespace(tmp_path):
    emu = emulator_for(tmp_path, {**FUNCTIONS, "minecraft:hello": "return 7"}, TAGS)
    emu.call("#minecraft:load")
    assert emu.score("#n", "o") == 0
    assert emu.call("hello") == 7


def test_call_as_missing_entity_is_a_clear_error(tmp_path):
    emu = emulator_for(tmp_path, FUNCTIONS, TAGS)
    with pytest.raises(ValueError, match="finds 0 entities"):
        emu.call("t:work", as_="@e")


def test_use_before_load():
    with pytest.raises(RuntimeError, match="load"):
        Emulator().tick()


def test_unknown_backend():
    with pytest.raises(ValueError, match="unknown backend"):
        Emulator(backend="java")
