"""``stopwatch`` and ``execute if stopwatch`` (1.21.11+) on both backends, as StopwatchCommand and
ExecuteCommand.checkStopwatch do them (decompiled 1.21.11): the elapsed seconds (Stopwatch.elapsedSeconds:
milliseconds / 1000.0), the query's result (int)(seconds * scale), saturated as Java casts; create
fails on an id in use, the others on an id not in use. The game's clock is real time; the emulator's
is 50 ms per server tick (a server at its 20 ticks a second)."""
import pytest

from emulator import Emulator
from tests.world.world_emulator import make_pack


def scores(emu, *holders):
    return [emu.score(h, "o") for h in holders]


def run(tmp_path, backend):
    emu = Emulator(backend=backend)
    emu.load(make_pack(tmp_path / "p", {
        "t:setup": "scoreboard objectives add o dummy",
        "t:start": "stopwatch create t:w\nstopwatch create lap",
        "t:read": "\n".join([
            "execute store result score #ms o run stopwatch query t:w 1000",
            "execute store result score #s o run stopwatch query t:w",
            "execute store result score #huge o run stopwatch query t:w 1000000000000",
            "execute store result score #neg o run stopwatch query minecraft:lap -2000",
            "execute store success score #at_least_1 o if stopwatch t:w 1..",
            "execute store success score #under_1 o if stopwatch t:w ..0.999",
        ]),
        "t:restart": "stopwatch restart t:w\nstopwatch remove lap",
        "t:fail": "\n".join([
            "execute store success score #dup o run stopwatch create t:w",
            "execute store success score #gone o run stopwatch query lap",
            "execute store success score #gone_if o if stopwatch lap 0..",
            "execute store success score #remove_gone o run stopwatch remove lap",
        ]),
    }), "1.21.11")
    emu.call("t:setup")
    return emu


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_stopwatch_counts_the_ticks_as_a_20_tick_server_would(tmp_path, backend):
    emu = run(tmp_path, backend)
    emu.call("t:start")
    emu.call("t:read")
    assert scores(emu, "#ms", "#s", "#at_least_1", "#under_1") == [0, 0, 0, 1]  # within one tick
    emu.tick(30)
    emu.call("t:read")
    assert scores(emu, "#ms", "#s", "#huge", "#neg", "#at_least_1", "#under_1") == [
        1500, 1, 2147483647, -3000, 1, 0]  # 1.5 s; a product past an int saturates
    emu.call("t:restart")
    emu.tick(4)
    emu.call("t:read")
    assert scores(emu, "#ms", "#under_1") == [200, 1]


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_ids_in_use_and_missing_fail(tmp_path, backend):
    emu = run(tmp_path, backend)
    emu.call("t:start")
    emu.call("t:restart")  # lap removed
    emu.call("t:fail")
    assert scores(emu, "#dup", "#gone", "#gone_if", "#remove_gone") == [0, 0, 0, 0]
