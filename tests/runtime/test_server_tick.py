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


# ---------------------------------------------------------------------- batches of ticks
def _observed(emu) -> dict:
    """What a run of ticks leaves that a pack or a user can see."""
    profile = emu.profile
    return {
        "scores": emu.scores(), "ticks": emu.commands_per_tick, "max_root": emu.max_root_cost,
        "clocks": (emu.ticks, emu.state.gametime, emu.state.daytime),
        "diagnostics": [(d.message, d.severity, tuple(f.function for f in d.frames)) for d in emu.diagnostics],
        "log": [(e.tick, e.kind, e.text) for e in emu.log],
        "overflows": [(o.tick, o.function, o.loc.line, o.exact) for o in emu.overflows],
        "roots": {f: vars(r) for f, r in profile.roots.items()}, "functions": profile.functions_self,
    }


def _ticks_three_ways(tmp_path, functions, tags, ticks, sanitize=False):
    """The same ticks run by ``tick(ticks)`` on the VM (batched), by one ``tick()`` at a time on the
    VM, and on the reference backend: what each left."""
    seen = []
    for backend, batched in (("numba", True), ("numba", False), ("python", False)):
        emu = emulator_for(tmp_path / f"{backend}{batched}", functions, tags=tags, backend=backend, sanitize=sanitize)
        emu.start()
        if batched:
            assert emu.tick(ticks) == sum(emu.commands_per_tick)
        else:
            for _ in range(ticks):
                emu.tick()
        seen.append(_observed(emu))
    return seen


def test_a_batch_of_quiet_ticks_runs_as_tick_by_tick(tmp_path):
    functions = {"t:load": SETUP + "scoreboard players set #ten o 10\nsummon marker 0 0 0\nsummon marker 1 0 0",
                 "t:a": "scoreboard players add #a o 1\nexecute if score #a o matches 3.. run function t:c",
                 "t:b": "scoreboard players operation #b o += #a o",
                 "t:c": "scoreboard players operation #c o += #ten o\nexecute as @e run scoreboard players add #n o 1\n"
                        "execute as @e at @s run tp @s ~ ~0.5 ~\nexecute as @e[x=0,y=10,z=0,distance=..1] run "
                        "scoreboard players add @s o 1"}
    batched, stepped, reference = _ticks_three_ways(tmp_path, functions, {"minecraft:load": ["t:load"],
                                                                          "minecraft:tick": ["t:a", "t:b"]}, 50)
    assert batched == stepped == reference
    assert batched["scores"]["o"]["#b"] == sum(range(1, 51)) and batched["clocks"] == (50, 50, 50)


def test_host_ops_schedules_and_daylight_in_a_batch_read_their_tick(tmp_path):
    # a host op every 7 ticks reads the game time and schedules a function; the rule stops the day
    # time on tick 30: each is seen at its tick, as one tick() at a time sees it
    functions = {
        "t:load": SETUP,
        "t:tick": "scoreboard players add #t o 1\n"
                  "execute if score #t o matches 7 run schedule function t:later 5t\n"
                  "execute if score #t o matches 14 run execute store result score #gt o run time query gametime\n"
                  "execute if score #t o matches 30 run gamerule doDaylightCycle false\n"
                  "execute if score #t o matches 40 run execute store result score #day o run time query daytime",
        "t:later": "execute store result score #later o run time query gametime\n"
                   "schedule function t:later 9t",
    }
    batched, stepped, reference = _ticks_three_ways(tmp_path, functions, {"minecraft:load": ["t:load"],
                                                                          "minecraft:tick": ["t:tick"]}, 60)
    assert batched == stepped == reference
    assert batched["scores"]["o"]["#gt"] == 13 and batched["scores"]["o"]["#day"] == 29
    assert batched["scores"]["o"]["#later"] == 56


def test_cuts_overflows_and_log_lines_in_a_batch_keep_their_tick(tmp_path):
    body = "".join("scoreboard players add #n o 1\n" for _ in range(8))
    functions = {
        "t:load": SETUP + "gamerule maxCommandChainLength 6\nscoreboard players set #big o 2147483000\n"
                          "scoreboard players set #k o 100",
        "t:x": "scoreboard players add #t o 1\nexecute if score #t o matches 20 run function t:long",
        "t:long": body,
        "t:y": "execute if score #t o matches 33 run scoreboard players operation #big o *= #k o\n"
               "execute if score #t o matches 41 run tellraw @a \"hi\"",
    }
    batched, stepped, reference = _ticks_three_ways(tmp_path, functions, {"minecraft:load": ["t:load"],
                                                                          "minecraft:tick": ["t:x", "t:y"]}, 45,
                                                    sanitize=True)
    assert batched == stepped == reference
    assert [o[0] for o in batched["overflows"]] == [32]  # the 33rd tick (ticks count from 0)
    assert any("stopped due to limit" in d[0] for d in batched["diagnostics"])


def test_effects_and_players_tick_each_tick(tmp_path):
    # a running effect or a player's statistics need each tick's end: no batching past them
    functions = {"t:load": SETUP + "scoreboard objectives add played minecraft.custom:minecraft.play_time\n"
                                   "summon zombie 0 0 0 {Tags:[z]}\neffect give @e[tag=z] slowness 2",
                 "t:tick": "scoreboard players add #t o 1\n"
                           "execute store result score #slow o run data get entity @e[tag=z,limit=1] "
                           "active_effects[0].duration"}
    seen = []
    for backend in ("numba", "python"):
        emu = emulator_for(tmp_path / backend, functions, tags={"minecraft:load": ["t:load"],
                                                                "minecraft:tick": ["t:tick"]}, backend=backend)
        emu.start()
        emu.add_player("Steve")
        emu.tick(50)
        seen.append(_observed(emu))
    assert seen[0] == seen[1]
    assert seen[0]["scores"]["o"]["#slow"] == 0 and seen[0]["scores"]["played"]["Steve"] == 50


def test_a_block_tick_due_in_a_batch_runs_at_its_tick(tmp_path):
    emu = emulator_for(tmp_path, {"t:load": SETUP, "t:tick": "scoreboard players add #t o 1"},
                       tags={"minecraft:load": ["t:load"], "minecraft:tick": ["t:tick"]})
    emu.start()
    ran = []
    air = emu.state.blocks.get((0, 0, 0)).id
    emu.state.block_ticks.schedule((0, 0, 0), air, 17, emu.state.gametime,
                                   lambda state, pos: ran.append((state.gametime, state.scoreboard.get("#t", "o"))))
    emu.tick(40)
    assert ran == [(17, 17)] and emu.score("#t", "o") == 40
