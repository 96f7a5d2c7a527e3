"""Players joining and leaving at any tick (emulator.world.players, Emulator.add_player /
remove_player / place_player, ``dpemu run --player``).

Sources (decompiled 1.21): server/players/PlayerList.java (placeNewPlayer,
disconnectAllPlayersWithProfile, remove: Stats.LEAVE_GAME), core/UUIDUtil.java.
"""
import json

import pytest
from click.testing import CliRunner

from emulator import Emulator
from emulator.cli import main
from emulator.world.players import offline_uuid
from emulator.world.entities import uuid_string

SETUP = {"t/function/init.mcfunction": "scoreboard objectives add left minecraft.custom:minecraft.leave_game\n"
                                       "scoreboard objectives add n dummy\n",
         "t/function/count.mcfunction": "execute store result score #players n if entity @a\n",
         "t/function/standing.mcfunction": "execute store result score #standing n if entity @a[nbt={OnGround:1b}]\n",
         "t/function/order.mcfunction": "scoreboard players set #i n 0\n"
                                        "execute as @a run function t:mark\n",
         "t/function/mark.mcfunction": "scoreboard players add #i n 1\nscoreboard players operation @s n = #i n\n"}


@pytest.fixture(params=["python", "numba"])
def emu(request, pack):
    emu = Emulator(backend=request.param)
    emu.load(pack(SETUP, load=["t:init"]))
    emu.start()
    return emu


def test_a_player_joins_at_any_tick_with_the_offline_uuid_of_its_name(emu):
    emu.tick(5)
    uuid = emu.add_player("Alex", (1, 2, 3))
    assert uuid == uuid_string(offline_uuid("Alex"))
    emu.call("t:count")
    assert emu.score("#players", "n") == 1


def test_leaving_counts_leave_game_and_keeps_the_scores(emu):
    emu.add_player("Alex")
    emu.set_score("Alex", "n", 7)
    emu.remove_player("Alex")
    emu.call("t:count")
    assert emu.score("#players", "n") == 0
    assert emu.score("Alex", "left") == 1 and emu.score("Alex", "n") == 7
    first = emu.add_player("Alex")  # rejoins: same UUID, same scores
    assert first == uuid_string(offline_uuid("Alex")) and emu.score("Alex", "n") == 7
    with pytest.raises(ValueError, match="no player named 'Sam'"):
        emu.remove_player("Sam")


def test_joining_again_under_a_name_online_disconnects_the_first(emu):
    emu.add_player("Alex")
    emu.add_player("Alex", (5, 0, 0))
    emu.call("t:count")
    assert emu.score("#players", "n") == 1 and emu.score("Alex", "left") == 1


def test_players_are_visited_in_join_order(emu):
    for name in ("Alex", "Steve", "Sam"):
        emu.add_player(name)
    emu.remove_player("Alex")
    emu.add_player("Alex")  # back at the end of the list
    emu.call("t:order")
    assert [emu.score(n, "n") for n in ("Steve", "Sam", "Alex")] == [1, 2, 3]


def test_place_player_moves_and_lands(emu):
    emu.add_player("Alex", on_ground=False)
    emu.call("t:standing")
    assert emu.score("#standing", "n") == 0
    emu.place_player("Alex", pos=(4, 5, 6), rotation=(90, 10), on_ground=True)
    emu.call("t:standing")
    assert emu.score("#standing", "n") == 1
    [alex] = emu.entities("@a")
    assert alex["pos"] == [4.0, 5.0, 6.0] and alex["rotation"] == [90.0, 10.0]


def test_a_player_a_client_drives_stays_where_placed(emu):
    # ServerPlayer.tick does not call travel: a client's player moves only by its packets, so one
    # placed in the air is not pulled down by the server (PackTest's dummies are: test_dummy_falling)
    emu.add_player("Alex", pos=(0.5, 10.0, 0.5), on_ground=False)
    emu.tick(40)
    emu.call("t:standing")
    assert emu.score("#standing", "n") == 0
    [alex] = emu.entities("@a")
    assert alex["pos"] == [0.5, 10.0, 0.5]
    assert emu.diagnostics == []


def test_run_player_in_the_air(pack, tmp_path):
    root = pack(SETUP, load=["t:init"], tick=["t:standing"])
    out = tmp_path / "run.json"
    result = CliRunner().invoke(main, ["run", str(root), "--ticks", "1", "--player", "A@0,0,0", "--player",
                                       "B@0,5,0,0,0,air", "--watch", "#standing n", "--json", str(out)])
    assert result.exit_code == 0, result.output
    assert json.loads(out.read_text())["watch"] == {"#standing n": 1}  # A stands, B is in the air
    bad = CliRunner().invoke(main, ["run", str(root), "--player", "A@0,0,nan"])
    assert bad.exit_code == 2 and "finite numbers" in bad.output


def test_run_player_in_a_dimension(pack, tmp_path):
    root = pack(SETUP, load=["t:init"])
    out = tmp_path / "run.json"
    result = CliRunner().invoke(main, ["run", str(root), "--player", "A@0,0,0,air,in=the_nether", "--json", str(out)])
    assert result.exit_code == 0, result.output
    [player] = json.loads(out.read_text())["entities"]
    assert player["dimension"] == "minecraft:the_nether"
    bad = CliRunner().invoke(main, ["run", str(root), "--player", "A@0,0,0,in=t:nowhere"])
    assert bad.exit_code == 2 and "t:nowhere" in bad.output


def test_what_a_world_keeps_on_its_players_stays_in_that_world(pack):
    """A player's death, hurt timer, last attacker and swing are kept by its own world (WorldState):
    a world made after it neither ticks its dead player's DeathTime (LivingEntity.tickDeath) nor
    sees its timers."""
    files = {"t/function/die.mcfunction": "kill @a\n", "t/function/hurt.mcfunction": "damage @a 1\n"}
    first = Emulator(backend="python")
    first.load(pack(files))
    first.add_player("Alex")
    first.add_player("Steve")
    first.call("t:die", as_="Alex")
    first.call("t:hurt")
    dead = first.state.entities.players()[0]
    assert dead.data["DeathTime"] == 0 and first.state.dead_players and first.state.hurt_timers
    second = Emulator(backend="python")
    second.load(pack(files))
    assert not second.state.dead_players and not second.state.hurt_timers and not second.state.swung
    second.tick(5)
    assert dead.data["DeathTime"] == 0
    first.tick(5)
    assert dead.data["DeathTime"] == 5
