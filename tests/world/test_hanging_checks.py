"""Item frames check every 101 ticks that they can stay (BlockAttachedEntity.tick, ItemFrame.survives
and dropItem; decompiled 26.1.2 and 1.21.3), and a removed entity takes its scores and team with it
(ServerLevel.EntityCallbacks.onDestroyed -> Scoreboard.entityRemoved)."""
import pytest

from emulator.api import Emulator
from tests.conftest import write_pack

BACKENDS = ["numba", "python"]
SETUP = ("scoreboard objectives add o dummy\n"
         "setblock 0 64 0 stone\n"
         "summon item_frame 0 65 0 {Facing:1b,Tags:[\"on\"],Item:{id:\"minecraft:apple\",count:1}}\n"
         "summon item_frame 5 70 5 {Tags:[\"off\"],Item:{id:\"minecraft:apple\",count:1}}\n"
         "summon item_frame 9 70 9 {Tags:[\"fixed\"],Fixed:1b}\n"
         "scoreboard players set @e[tag=off] o 7\n")


def _world(tmp_path, backend, extra=""):
    root = write_pack(tmp_path / "p", {"t/function/load.mcfunction": SETUP + extra,
                                       "t/function/count.mcfunction":
                                       "execute store result score #frames o if entity @e[type=item_frame]\n"
                                       "execute store result score #apples o if entity @e[type=item,"
                                       "nbt={Item:{id:\"minecraft:apple\"}}]\n"
                                       "execute store result score #items o if entity @e[type=item,"
                                       "nbt={Item:{id:\"minecraft:item_frame\"}}]\n"}, load=["t:load"])
    emu = Emulator(backend=backend)
    emu.load(root)
    emu.start()
    return emu


def _counts(emu):
    emu.call("t:count")
    return emu.score("#frames", "o"), emu.score("#apples", "o"), emu.score("#items", "o")


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_frame_with_nothing_behind_it_breaks_on_its_101st_tick(tmp_path, backend):
    # checkInterval counts 0..100: the check comes on the tick it reaches 100; the frame in the air
    # (down, with air above it) drops its frame item and its apple; the one on stone and the fixed stay
    emu = _world(tmp_path, backend)
    emu.tick(100)
    assert _counts(emu) == (3, 0, 0)
    emu.tick(1)
    assert _counts(emu) == (2, 1, 1)
    assert emu.score("@e[tag=off]", "o") is None
    assert [d for d in emu.diagnostics if d.unmodelled] == []


@pytest.mark.parametrize("backend", BACKENDS)
def test_its_scores_go_with_it(tmp_path, backend):
    emu = _world(tmp_path, backend, "execute as @e[tag=off] run scoreboard players operation #uuid o = @s o\n"
                                    "team add t\nteam join t @e[tag=off]\n")
    before = {h for h in emu.scores().get("o", {})}
    emu.tick(101)
    after = {h for h in emu.scores().get("o", {})}
    assert len(before - after) == 1  # the broken frame's UUID holder (Scoreboard.resetAllPlayerScores)
    assert emu.state.teams.teams["t"].members == []  # removePlayerFromTeam


@pytest.mark.parametrize("backend", BACKENDS)
def test_no_drop_chance_and_no_entity_drops(tmp_path, backend):
    # ItemFrame.dropItem: the item only when random.nextFloat() < ItemDropChance (never at 0);
    # nothing at all without doEntityDrops
    emu = _world(tmp_path, backend, "data merge entity @e[tag=off,limit=1] {ItemDropChance:0.0f}\n")
    emu.tick(101)
    assert _counts(emu) == (2, 0, 1)
    emu = _world(tmp_path / "2", backend, "gamerule doEntityDrops false\n")
    emu.tick(101)
    assert _counts(emu) == (2, 0, 0)


def test_a_painting_s_check_is_not_modelled(tmp_path):
    emu = _world(tmp_path, "python", "summon painting 20 70 20\n")
    emu.tick(101)
    assert any("hanging entity's check" in d.message for d in emu.diagnostics if d.unmodelled)
