"""The tick loop: #load once, #tick members each tick, schedule ordering (ServerFunctionManager,
ServerLevel.tickTime, TimerQueue, ScheduleCommand in the decompiled 1.21 sources)."""
from __future__ import annotations

import pytest

from tests.vm.helpers import SETUP, emulator_for

BACKENDS = ["numba", "python"]


def trace(step: int) -> str:
    """Append ``step`` as a decimal digit to #trace (#trace = #trace * 10 + step)."""
    return f"scoreboard players operation #trace o *= #ten o\nscoreboard players add #trace o {step}\n"


@pytest.mark.parametrize("backend", BACKENDS)
def test_load_once_then_tick_members_in_order(tmp_path, backend):
    functions = {
        "t:load": SETUP + "scoreboard players set #ten o 10\nscoreboard players add #loads o 1",
        "t:a": "scoreboard players add #a o 1\nexecute store result score #gt o run time query gametime",
        "t:b": "scoreboard players operation #b o = #a o",
    }
    emu = emulator_for(tmp_path, functions, tags={"minecraft:load": ["t:load"], "minecraft:tick": ["t:a", "t:b"]},
                       backend=backend)
    emu.tick(3)
    assert emu.score("#loads", "o") == 1
    assert emu.score("#a", "o") == 3
    assert emu.score("#b", "o") == 3  # t:b runs after t:a in the same tick
    assert emu.score("#gt", "o") == 2  # tick functions run before the game time advances
    assert emu.state.gametime == 3 and emu.ticks == 3
    assert len(emu.commands_per_tick) == 3


@pytest.mark.parametrize("backend", BACKENDS)
def test_schedule_order_by_time_then_insertion(tmp_path, backend):
    functions = {
        "t:load": SETUP + "scoreboard players set #ten o 10\n"
                          "schedule function t:s3 3t\nschedule function t:s1 1t\nschedule function t:s2 1t\n"
                          "schedule function t:late 2t\nschedule function t:late 4t replace\n"
                          "schedule function t:twice 2t append\nschedule function t:twice 3t append\n"
                          "schedule function t:twice 3t append",
        "t:s1": trace(1), "t:s2": trace(2), "t:s3": trace(3), "t:late": trace(4), "t:twice": trace(5),
    }
    emu = emulator_for(tmp_path, functions, tags={"minecraft:load": ["t:load"]}, backend=backend)
    emu.tick(1)
    assert emu.score("#trace", "o") == 12  # due at gametime 1, run in the first tick after it advances
    emu.tick(4)
    # gametime 2: twice; 3: s3, twice (same name and time added once); 4: late (replaced 2t)
    assert emu.score("#trace", "o") == 125354


@pytest.mark.parametrize("backend", BACKENDS)
def test_each_tick_member_has_its_own_quota(tmp_path, backend):
    body = "".join("scoreboard players add #n o 1\n" for _ in range(8))
    functions = {"t:load": SETUP + "gamerule maxCommandChainLength 5", "t:x": body, "t:y": body}
    emu = emulator_for(tmp_path, functions, tags={"minecraft:load": ["t:load"], "minecraft:tick": ["t:x", "t:y"]},
                       backend=backend)
    emu.tick(1)
    assert emu.score("#n", "o") == 8  # 4 adds in each root
    cuts = [d for d in emu.diagnostics if "stopped due to limit" in d.message]
    assert [d.frames[-1].function for d in cuts] == ["t:x", "t:y"]


def test_schedule_clear_and_scheduled_tag(tmp_path):
    functions = {
        "t:load": SETUP + "schedule function #t:both 1t\nschedule function t:gone 1t\nschedule clear t:gone",
        "t:a": "scoreboard players add #a o 1", "t:b": "scoreboard players add #b o 1",
        "t:gone": "scoreboard players add #gone o 1",
    }
    emu = emulator_for(tmp_path, functions, tags={"minecraft:load": ["t:load"], "t:both": ["t:a", "t:b"]})
    emu.tick(2)
    assert (emu.score("#a", "o"), emu.score("#b", "o"), emu.score("#gone", "o")) == (1, 1, None)


@pytest.mark.parametrize("backend", BACKENDS)
def test_root_listeners_hear_every_root(tmp_path, backend):
    functions = {"t:load": SETUP, "t:tick": "scoreboard players add #n o 1", "t:later": "return 3",
                 "t:soon": "schedule function t:later 1t"}
    emu = emulator_for(tmp_path, functions, tags={"minecraft:load": ["t:load"], "minecraft:tick": ["t:tick"]},
                       backend=backend)
    heard = []
    emu.runtime.root_listeners.append(lambda function, result: heard.append((function, result.cost, result.result)))
    emu.start()
    emu.call("t:soon")
    emu.tick(2)
    assert heard == [("t:load", 2, None), ("t:soon", 2, None), ("t:tick", 2, None), ("t:later", 1, 3),
                     ("t:tick", 2, None)]
