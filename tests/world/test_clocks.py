"""26.1's world clocks on both backends: ``time`` on the default clock and ``time of <clock>``,
time markers, timelines, pause, resume and rate, and how the clocks tick.

Sources (26.1.2, decompiled): server/commands/TimeCommand.java (every result: setTotalTicks returns
the ticks set, the others wrapTime(ticks) = ticks % Integer.MAX_VALUE, pause/resume/rate 1;
getDefaultClock), world/clock/ServerClockManager.java (setTotalTicks, addTicks clamped at 0,
moveToTimeMarker, tick: only with advance_time, ClockInstance.tick's float fraction),
world/clock/ClockTimeMarker.java (resolveTimeToMoveTo), world/timeline/Timeline.java
(getCurrentTicks, getPeriodCount), world/timeline/Timelines.java (minecraft:day's markers),
data/worldgen/DimensionTypes.java (default clocks), server/MinecraftServer.tickChildren (the
clocks tick after the functions, before the levels: before the scheduled functions).
"""
from __future__ import annotations

import json

import numpy as np
import pytest

from emulator import Emulator
from tests.world.world_emulator import make_pack

BACKENDS = ["python", "numba"]
DAY = {"clock": "minecraft:overworld", "period_ticks": 24000}


def clock_world(tmp_path, backend, functions, files=None, version="26.1"):
    root = make_pack(tmp_path / "p", {"t:setup": "scoreboard objectives add o dummy", **functions})
    formats = {"26.1": 101, "1.21.11": 94}[version]
    (root / "pack.mcmeta").write_text(json.dumps({"pack": {"description": "t", "min_format": formats,
                                                           "max_format": formats}}))
    for name, value in (files or {}).items():
        path = root / "data" / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(value))
    emu = Emulator(backend=backend)
    emu.load(root)
    assert not emu.packs.errors, [d.format() for d in emu.packs.errors]
    emu.call("t:setup")
    return emu


@pytest.mark.parametrize("backend", BACKENDS)
def test_set_add_and_query_the_default_clock(tmp_path, backend):
    emu = clock_world(tmp_path, backend, {"t:main": "\n".join([
        "execute store result score #set o run time set 30000",  # the ticks set, not % 24000
        "execute store result score #add o run time add 20000",  # wrapTime(50000)
        "execute store result score #time o run time query time",
        "execute store result score #day o run time query day",  # minecraft:day: 50000 % 24000
        "execute store result score #days o run time query day repetition",  # 50000 / 24000
        "execute store result score #moon o run time query moon repetition",  # period 8 days: 0
        "execute store result score #early o run time query early_game",  # no period: the clock's ticks
        "execute store result score #back o run time add -60000",  # clamped at 0
        "execute store result score #game o run time query gametime",
    ])})
    emu.call("t:main")
    scores = [emu.score(h, "o") for h in ("#set", "#add", "#time", "#day", "#days", "#moon", "#early", "#back", "#game")]
    assert scores == [30000, 50000, 50000, 2000, 2, 0, 50000, 0, 0]
    assert emu.state.daytime == 0  # the overworld clock is the world's day time


@pytest.mark.parametrize("backend", BACKENDS)
def test_time_markers_move_the_clock_forward(tmp_path, backend):
    emu = clock_world(tmp_path, backend, {
        "t:at": "execute store result score #r o run time set 25000",
        # minecraft:day's markers (Timelines.bootstrap): day 1000, noon 6000, night 13000, midnight 18000
        "t:noon": "execute store result score #r o run time set noon",
        "t:day": "execute store result score #r o run time set minecraft:day",
        "t:sleep": "execute store success score #r o run time set wake_up_from_sleep",
        "t:none": "execute store success score #r o run time set t:dawn",
    })
    emu.call("t:at")
    emu.call("t:noon")  # 25000 % 24000 = 1000 -> 6000: +5000
    assert (emu.score("#r", "o"), emu.state.daytime) == (30000, 30000)
    emu.call("t:noon")  # already at noon: a whole period on
    assert emu.score("#r", "o") == 54000
    emu.call("t:day")  # 54000 % 24000 = 6000 -> 1000 of the next day
    assert emu.score("#r", "o") == 73000
    emu.call("t:sleep")  # a marker not shown in commands still moves the clock
    assert (emu.score("#r", "o"), emu.state.daytime) == (1, 96000)
    emu.call("t:none")  # commands.time.no_time_marker_found
    assert (emu.score("#r", "o"), emu.state.daytime) == (0, 96000)


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_packs_clock_and_timeline(tmp_path, backend):
    files = {"t/world_clock/season.json": {},
             "t/timeline/year.json": {"clock": "t:season", "period_ticks": 100,
                                      "time_markers": {"t:spring": {"ticks": 10, "show_in_commands": True},
                                                       "t:fall": 60}},
             "t/timeline/once.json": {"clock": "t:season", "time_markers": {"t:end": 250}}}
    emu = clock_world(tmp_path, backend, {"t:main": "\n".join([
        "execute store result score #fall o run time of t:season set t:fall",
        "execute store result score #add o run time of t:season add 345",
        "execute store result score #year o run time of t:season query t:year",  # 405 % 100
        "execute store result score #years o run time of t:season query t:year repetition",
        "execute store result score #once o run time of t:season query t:once repetition",  # no period: 0
        "execute store result score #end o run time of t:season set t:end",  # no period: the marker's ticks
        "execute store success score #wrong o run time of t:season query minecraft:day",
        "execute store result score #overworld o run time query time",
    ])}, files)
    emu.call("t:main")
    scores = [emu.score(h, "o") for h in ("#fall", "#add", "#year", "#years", "#once", "#end", "#wrong", "#overworld")]
    assert scores == [60, 405, 5, 4, 0, 250, 0, 0]


@pytest.mark.parametrize("backend", BACKENDS)
def test_each_dimension_reads_its_default_clock(tmp_path, backend):
    # DimensionTypes.bootstrap: the end has its own clock, the nether none (commands.time.no_default_clock)
    emu = clock_world(tmp_path, backend, {"t:main": "\n".join([
        "time set 500",
        "execute in minecraft:the_end run time set 7",
        "execute store result score #o o run time query time",
        "execute store result score #e o run time of minecraft:the_end query time",
        "execute store success score #n o in minecraft:the_nether run time query time",
        "execute store result score #n2 o in minecraft:the_nether run time of overworld query time",
    ])})
    emu.call("t:main")
    assert [emu.score(h, "o") for h in ("#o", "#e", "#n", "#n2")] == [500, 7, 0, 500]


@pytest.mark.parametrize("backend", BACKENDS)
def test_clocks_tick_with_their_rate_unless_paused(tmp_path, backend):
    emu = clock_world(tmp_path, backend, {
        "t:slow": "execute store result score #r o run time of the_end rate 0.3",
        "t:pause": "execute store result score #r o run time pause",
        "t:resume": "time resume",
        "t:off": "gamerule advance_time false",
        "t:q": "execute store result score #o o run time query time\n"
               "execute store result score #e o run time of the_end query time",
    })
    emu.call("t:slow")
    emu.call("t:pause")
    assert emu.score("#r", "o") == 1
    emu.tick(10)
    emu.call("t:q")
    # the end clock: a float fraction gaining 0.3 each tick (ClockInstance.tick)
    partial, ticks = np.float32(0), 0
    for _ in range(10):
        partial = np.float32(partial + np.float32(0.3))
        whole = int(np.floor(partial))
        partial, ticks = np.float32(partial - np.float32(whole)), ticks + whole
    assert (emu.score("#o", "o"), emu.score("#e", "o")) == (0, ticks) and ticks == 3
    emu.call("t:resume")
    emu.tick(4)
    emu.call("t:q")
    assert emu.score("#o", "o") == 4
    emu.call("t:off")  # advance_time off: no clock moves
    emu.tick(5)
    emu.call("t:q")
    assert emu.score("#o", "o") == 4


@pytest.mark.parametrize("backend", BACKENDS)
def test_the_clocks_tick_before_the_scheduled_functions(tmp_path, backend):
    emu = clock_world(tmp_path, backend, {
        "t:start": "schedule function t:later 1t",
        "t:later": "execute store result score #at o run time query time",
    })
    emu.call("t:start")
    emu.tick(1)
    assert emu.score("#at", "o") == 1  # before 26.1 the day time moved after the scheduled functions


def test_older_releases_keep_the_day_time(tmp_path):
    emu = clock_world(tmp_path, "python", {"t:main": "execute store result score #s o run time set 30000\n"
                                                     "execute store result score #d o run time set day"},
                      version="1.21.11")
    emu.call("t:main")
    assert (emu.score("#s", "o"), emu.score("#d", "o"), emu.state.clocks) == (6000, 1000, None)
