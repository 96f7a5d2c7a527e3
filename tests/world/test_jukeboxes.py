"""Jukeboxes playing (emulator.world.jukeboxes), on both backends. Sources (decompiled 1.21):
JukeboxBlockEntity.tick / loadAdditional / setTheItem, JukeboxSongPlayer.play / stop / tick,
JukeboxSong.lengthInTicks / hasFinished, JukeboxSongs (11: 71 seconds)."""
import pytest

from tests.world.world_emulator import emulator


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_disc_put_in_plays_until_its_song_ends(tmp_path, backend):
    # setTheItem: play from tick 0; tick: one more each tick until hasFinished (71 s x 20 + 20 = 1440), then stop
    emu = emulator(tmp_path, backend, {"t:p": "setblock 0 0 0 jukebox\n"
                                              "item replace block 0 0 0 container.0 with music_disc_11"})
    emu.call("t:p")
    nbt = emu.state.blocks.entity((0, 0, 0))
    assert int(nbt["ticks_since_song_started"]) == 0
    emu.tick(1440)
    assert int(nbt["ticks_since_song_started"]) == 1440
    emu.tick(1)
    assert "ticks_since_song_started" not in nbt and str(nbt["RecordItem"]["id"]) == "minecraft:music_disc_11"
    assert not [d for d in emu.diagnostics if d.unmodelled]


def test_only_a_song_saved_as_playing_plays(tmp_path):
    # loadAdditional: the song is set only with ticks_since_song_started saved; a stick has no song
    emu = emulator(tmp_path, "python", {"t:p": "\n".join([
        "setblock 0 0 0 jukebox{RecordItem:{id:'minecraft:music_disc_cat',count:1}}",
        "setblock 2 0 0 jukebox{RecordItem:{id:'minecraft:music_disc_cat',count:1},ticks_since_song_started:5L}",
        "setblock 4 0 0 jukebox{RecordItem:{id:'minecraft:stick',count:1},ticks_since_song_started:5L}"])})
    emu.call("t:p")
    emu.tick(3)
    blocks = emu.state.blocks
    assert "ticks_since_song_started" not in blocks.entity((0, 0, 0))
    assert int(blocks.entity((2, 0, 0))["ticks_since_song_started"]) == 8
    assert int(blocks.entity((4, 0, 0))["ticks_since_song_started"]) == 5
    assert not [d for d in emu.diagnostics if d.unmodelled]


def test_taking_the_disc_out_stops_the_song(tmp_path):
    emu = emulator(tmp_path, "python", {"t:p": "setblock 0 0 0 jukebox\n"
                                               "item replace block 0 0 0 container.0 with music_disc_cat\n"
                                               "item replace block 0 0 0 container.0 with air"})
    emu.call("t:p")
    assert "ticks_since_song_started" not in emu.state.blocks.entity((0, 0, 0))
