"""The Emulator API: load, call, tick, run_until, scores, log, profile, diagnostics, backends."""
from __future__ import annotations

import subprocess
import sys

import pytest

from emulator import Emulator
from emulator.reference import ReferenceBackend
from tests.backends.programs import write_pack
from tests.vm.helpers import SETUP, emulator_for

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


def test_a_backend_object_runs_the_ticks(tmp_path):
    backend = ReferenceBackend()
    emu = Emulator(backend=backend)
    emu.load(write_pack(tmp_path / "pack", FUNCTIONS, TAGS))
    assert emu.backend is backend and emu.backend_name == "python"
    emu.tick(2)
    assert emu.score("#sq", "o") == 4


def test_the_python_backend_imports_no_numba(tmp_path):
    pack = write_pack(tmp_path / "pack", FUNCTIONS, TAGS)
    script = ("import sys\nimport emulator\nemu = emulator.Emulator(backend='python')\n"
              f"emu.load({str(pack)!r})\nemu.tick(2)\nassert emu.score('#sq', 'o') == 4\n"
              "print(sorted(m for m in sys.modules if m.split('.')[0] == 'numba'))")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True)
    assert done.stdout.strip() == "[]"


def test_profile_call_stacks_on_the_python_backend(tmp_path):
    emu = emulator_for(tmp_path, FUNCTIONS, TAGS, backend="python", stacks=True)
    emu.tick(2)
    profile = emu.profile
    assert sum(profile.stacks.values()) == sum(emu.commands_per_tick)
    assert profile.stacks[("t:tick", "t:work")] == 2 * 3 + 1  # its lines each tick, `say` at #n 2
    assert profile.calls == {"t:load": 1, "t:tick": 2, "t:work": 2}
    assert profile.functions_total["t:tick"] == 2 * (2 + 3) + 1
    assert profile.roots["t:tick"].runs == 2 and profile.roots["t:tick"].max_cost == 1 + 1 + 1 + 3 + 1


def test_call_stacks_need_a_backend_that_records_them():
    with pytest.raises(ValueError, match="numba backend records no call stacks"):
        Emulator(backend="numba", stacks=True)


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_start_runs_the_load_functions_once_before_any_tick(tmp_path, backend):
    emu = emulator_for(tmp_path, FUNCTIONS, TAGS, backend=backend)
    assert emu.start() > 0 and emu.score("#n", "o") == 0
    assert emu.start() == 0                      # loaded already: nothing runs again
    emu.set_score("#n", "o", 10)
    emu.tick()                                   # only #minecraft:tick: #n is not reset by t:load
    assert emu.score("#n", "o") == 11 and emu.ticks == 1


def test_players_earn_the_per_tick_statistics(tmp_path):
    # Player.tick (server side): play_time, total_world_time, time_since_death, time_since_rest
    # every tick; sneak_time while the sneak key is held; the criteria name statistics either way
    functions = {**FUNCTIONS, "t:load": FUNCTIONS["t:load"] + "\nscoreboard objectives add play minecraft.custom:"
                 "minecraft.play_time\nscoreboard objectives add rest custom:time_since_rest\n"
                 "scoreboard objectives add sneak minecraft.custom:minecraft.sneak_time"}
    emu = emulator_for(tmp_path, functions, TAGS)
    emu.add_player("Steve")
    emu.tick(3)
    emu.state.entities.by_holder("Steve").sneaking = True
    emu.run_until(lambda e: False, max_ticks=2)
    assert (emu.score("Steve", "play"), emu.score("Steve", "rest"), emu.score("Steve", "sneak")) == (5, 5, 2)
    assert emu.score("#n", "play") is None


def test_objectives_lists_the_ones_that_exist_now(tmp_path):
    pack = write_pack(tmp_path / "pack", {"t:main": "scoreboard objectives add a dummy\nscoreboard objectives add b dummy\n"
                                                    "scoreboard objectives remove a"})
    emu = Emulator(backend="python")
    emu.load(pack)
    emu.call("t:main")
    assert emu.objectives() == ["b"]


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_an_added_player_stands_on_the_ground_unless_told_otherwise(tmp_path, backend):
    # packs place things where a player stands (@s[nbt={OnGround:1b}]); the world has no terrain,
    # so the player's footing is the API's to say
    pack = write_pack(tmp_path / "pack", {"t:main": "scoreboard objectives add o dummy\n"
                                                    "execute as @a[nbt={OnGround:1b}] run scoreboard players add #ground o 1\n"
                                                    "execute as @a[nbt={OnGround:0b}] run scoreboard players add #air o 1"})
    emu = Emulator(backend=backend)
    emu.load(pack)
    emu.start()
    emu.add_player("Steve", (0, 64, 0))
    emu.tick()  # a join after the load
    emu.add_player("Alex", (0, 80, 0), on_ground=False)
    emu.call("t:main")
    assert (emu.score("#ground", "o"), emu.score("#air", "o")) == (1, 1)


WORLD = {
    "t:load": SETUP + "summon marker 0 0 0 {Tags:[m]}\nfunction t:place {n: 3}",
    "t:place": "$scoreboard players set #placed o $(n)",
    "t:tick": "execute as @e[tag=m] run scoreboard players add @s o 1\nscoreboard players add #n o 1\n"
              "execute if score #n o matches 2 run say two",
}


def _world(emu) -> tuple:
    return emu.scores(), emu.entities(), [(e.tick, e.text) for e in emu.log], emu.ticks, emu.commands_per_tick


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_new_world_runs_as_the_first_on_the_same_program(tmp_path, backend):
    emu = emulator_for(tmp_path, WORLD, TAGS, backend=backend)
    emu.tick(3)
    first = _world(emu)
    program = getattr(emu.backend, "program", None)
    emu.set_score("#stray", "o", 7)
    emu.new_world()
    assert emu.scores() == {} and emu.entities() == [] and emu.ticks == 0 and not emu.log
    emu.tick(3)
    assert _world(emu) == first
    assert first[0]["o"]["#placed"] == 3 and len(first[1]) == 1
    assert getattr(emu.backend, "program", None) is program      # not compiled again
