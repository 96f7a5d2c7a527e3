"""``bossbar`` and ``execute store ... bossbar`` on both backends.

Source (decompiled 1.21): server/commands/BossBarCommands.java (results: add/remove/list give the
number of bars, set value|max the new value, set name|color|style|visible 0, set players and get
players the player count, get visible 1/0; setting an unchanged property fails "Nothing changed");
server/bossevents/CustomBossEvent.java (defaults: value 0, max 100); ExecuteCommand.storeValue
(bossbar looked up at the stage; the callback sets value or max to the result or 1/0, unclamped).
"""
from __future__ import annotations

import pytest

from tests.world.world_emulator import emulator

BACKENDS = ["python", "numba"]


def run(tmp_path, backend, lines: list[str], players=()):
    """Each line stored as ``#<i>`` (result) and ``#ok<i>`` (success)."""
    body = "\n".join(f"execute store success score #ok{i} o store result score #{i} o run {line}"
                     for i, line in enumerate(lines))
    emu = emulator(tmp_path, backend, {"t:main": body})
    for name in players:
        emu.add_player(name)
    emu.call("t:main")
    return [(emu.score(f"#{i}", "o"), emu.score(f"#ok{i}", "o")) for i in range(len(lines))], emu


@pytest.mark.parametrize("backend", BACKENDS)
def test_bossbar_results(tmp_path, backend):
    results, emu = run(tmp_path, backend, [
        'bossbar add t:a "A"',            # 1 bar
        'bossbar add b "B"',              # minecraft:b: 2 bars
        'bossbar add t:a "again"',        # exists: fails
        "bossbar get t:a max",            # default 100
        "bossbar set t:a value 30",       # the new value
        "bossbar set t:a value 30",       # unchanged: fails
        "bossbar set t:a max 50",
        "bossbar get t:a value",
        "bossbar set t:a color red",      # 0
        "bossbar set t:a color red",      # unchanged: fails
        "bossbar set t:a visible false",  # 0
        "bossbar get t:a visible",        # 0 (hidden)
        "bossbar set t:a players @a",     # 2 players
        "bossbar get t:a players",
        "bossbar set t:a players @a",     # the same set: fails
        "bossbar set t:a players",        # nobody: 0
        "bossbar get nope value",         # unknown: fails
        "bossbar remove minecraft:b",     # 1 left
        "bossbar list",
    ], players=("Alex", "Steve"))
    assert results == [
        (1, 1), (2, 1), (0, 0), (100, 1), (30, 1), (0, 0), (50, 1), (30, 1), (0, 1), (0, 0),
        (0, 1), (0, 1), (2, 1), (2, 1), (0, 0), (0, 1), (0, 0), (1, 1), (1, 1),
    ]


@pytest.mark.parametrize("backend", BACKENDS)
def test_store_into_a_bossbar(tmp_path, backend):
    emu = emulator(tmp_path, backend, {"t:main": "\n".join([
        'bossbar add t:a "A"',
        "scoreboard players set #v o 250",
        "execute store result bossbar t:a value run scoreboard players get #v o",  # above max: kept
        "execute store success bossbar t:a max run scoreboard players get #unset o",  # fails: 0
        "execute store result score #value o run bossbar get t:a value",
        "execute store result score #max o run bossbar get t:a max",
        # an unknown bar fails the stage: the command does not run
        "execute store result bossbar t:nope value run scoreboard players set #ran o 1",
    ])})
    emu.call("t:main")
    assert (emu.score("#value", "o"), emu.score("#max", "o"), emu.score("#ran", "o")) == (250, 0, None)
