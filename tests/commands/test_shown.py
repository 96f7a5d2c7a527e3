"""The commands that show or play something to players: their results, which a pack can store
(decompiled 26.1.2 and 1.21.3: TitleCommand, ParticleCommand.sendParticles, ServerLevel.sendParticles,
PlaySoundCommand.playSound, StopSoundCommand, MsgCommand, DialogCommand)."""
from __future__ import annotations

import pytest

from emulator.api import Emulator
from tests.conftest import write_pack

BACKENDS = ["numba", "python"]


def results(tmp_path, backend, lines: dict[str, str], players=((0.0, 64.0, 0.0), (5.0, 64.0, 30.0)),
            mc: str | None = None) -> dict:
    """Each command's stored result (``store result``: 0 when it failed), with Alex and Steve online."""
    body = "\n".join(f"execute store result score {holder} o run {command}" for holder, command in lines.items())
    files = {"s/function/go.mcfunction": body, "s/function/load.mcfunction": "scoreboard objectives add o dummy"}
    emu = Emulator(backend=backend)
    emu.load(write_pack(tmp_path / "pack", files, load=["s:load"]), mc_version=mc)
    emu.start()
    for name, pos in zip(("Alex", "Steve"), players):
        emu.add_player(name, pos=pos)
    emu.call("s:go")
    return {holder: emu.score(holder, "o") for holder in lines}, emu


@pytest.mark.parametrize("backend", BACKENDS)
def test_title_stopsound_and_msg_count_their_players(tmp_path, backend):
    found, emu = results(tmp_path, backend, {
        "#title": 'title @a actionbar {"text":"hi"}', "#times": "title @a times 1 2 3", "#clear": "title Alex clear",
        "#stop": "stopsound @a", "#msg": "msg @a[name=Steve] hello", "#none": "title @a[name=Nobody] clear"})
    # each returns targets.size(); no player found fails (EntityArgument.getPlayers)
    assert found == {"#title": 2, "#times": 2, "#clear": 1, "#stop": 2, "#msg": 1, "#none": 0}
    steve = emu.entities("@a[name=Steve]")[0]["uuid"]
    # MsgCommand: the msg_command_incoming chat type, heard by the targets only
    assert [(e.kind, e.text, e.receivers) for e in emu.log] == [("msg", "Server whispers to you: hello", (steve,))]


@pytest.mark.parametrize("backend", BACKENDS)
def test_particles_reach_the_players_near_enough(tmp_path, backend):
    """ServerLevel.sendParticles: a player in the level whose block's centre is closer than 32
    blocks (512 with force) gets it; the result counts them and none fails."""
    found, _ = results(tmp_path, backend, {
        "#near": "particle minecraft:dust{color:[1.0,0.0,0.0],scale:1.0} 0 64 0 0 0 0 0 1",
        "#default": "particle flame 0 64 0",  # every player is a viewer
        "#far": "particle flame 100 64 0",
        "#force": "particle flame 100 64 0 0 0 0 0 1 force",
        "#forced_viewers": "particle flame 100 64 0 0 0 0 0 1 force @a[name=Alex]",
        "#out_of_force": "particle flame 1000 64 0 0 0 0 0 1 force",
        "#nether": "execute in the_nether run particle flame 0 64 0"})
    # Steve's block (5, 64, 30): its centre is 30.997 from (0.5, 64, 0.5)
    assert found == {"#near": 2, "#default": 2, "#far": 0, "#force": 2, "#forced_viewers": 1, "#out_of_force": 0,
                     "#nether": 0}


@pytest.mark.parametrize("backend", BACKENDS)
def test_sounds_reach_the_players_in_range(tmp_path, backend):
    """PlaySoundCommand: within 16 blocks, or 16 x the volume above 1; with a minimum volume
    everyone hears it; none fails; without targets the executing player (none for the server)."""
    found, _ = results(tmp_path, backend, {
        "#near": "playsound minecraft:entity.pig.ambient master @a 0 64 0",
        "#far": "playsound minecraft:entity.pig.ambient master @a 100 64 0",
        "#minimum": "playsound minecraft:entity.pig.ambient master @a 100 64 0 1 1 0.5",
        "#loud": "playsound minecraft:entity.pig.ambient master @a 0 64 40 3",
        "#caller": "playsound minecraft:entity.pig.ambient",
        "#as_alex": "execute as Alex at @s run playsound minecraft:entity.pig.ambient"})
    assert found == {"#near": 1, "#far": 0, "#minimum": 2, "#loud": 2, "#caller": 0, "#as_alex": 1}


@pytest.mark.parametrize("backend", BACKENDS)
def test_dialogs_count_their_players(tmp_path, backend):
    found, emu = results(tmp_path, backend, {"#show": "dialog show @a minecraft:server_links",
                                             "#clear": "dialog clear Alex", "#version": "version"}, mc="1.21.6")
    assert found == {"#show": 2, "#clear": 1, "#version": 1} and not emu.diagnostics  # VersionCommand: 1


@pytest.mark.parametrize("backend", BACKENDS)
def test_swing_counts_the_living(tmp_path, backend):
    found, _ = results(tmp_path, backend, {
        "#players": "swing @a offhand", "#marker": "execute summon marker run swing @s",
        "#executor": "execute as Alex run swing"}, mc="26.1")
    # SwingCommand: the living entities among the targets; none fails
    assert found == {"#players": 2, "#marker": 0, "#executor": 1}


@pytest.mark.parametrize("backend", BACKENDS)
def test_me_and_teammsg(tmp_path, backend):
    found, emu = results(tmp_path, backend, {
        "#setup": "team add red",
        "#join": "team join red Alex",
        "#me": "execute as Alex run me waves",
        "#team": "execute as Alex run teammsg hi",
        "#alone": "execute as Steve run teammsg hi"})
    # EmoteCommands returns 1; TeamMsgCommand counts the sender's team online (itself included);
    # without a team it fails
    assert (found["#me"], found["#team"], found["#alone"]) == (1, 1, 0)
    alex = emu.entities("@a[name=Alex]")[0]["uuid"]
    lines = [(e.kind, e.text, len(e.receivers)) for e in emu.log]
    assert lines == [("me", "* Alex waves", 2), ("teammsg", "-> [red] <Alex> hi", 1)]
    assert emu.log[-1].receivers == (alex,)


@pytest.mark.parametrize("mc, heard", [("1.21.4", 2), ("1.21.7", 0)])
def test_playsound_reaches_a_player_in_another_level_until_1_21_7(tmp_path, mc, heard):
    # PlaySoundCommand.playSound: 1.21.4 sends to every target within range whatever its level (as
    # 1.21.3); 1.21.7 skips a target in another level than the command's (none heard: it fails)
    found, _ = results(tmp_path, "python", {"#s": "playsound minecraft:block.note_block.harp master @a 0 64 0"},
                       players=((0.0, 64.0, 0.0), (1.0, 64.0, 1.0)), mc=mc)
    assert found == {"#s": 2}
    found, emu = results(tmp_path / "2", "python", {
        "#s": "execute in minecraft:the_nether run playsound minecraft:block.note_block.harp master @a 0 64 0"},
        players=((0.0, 64.0, 0.0), (1.0, 64.0, 1.0)), mc=mc)
    assert found == {"#s": heard}
