"""Command cost and the quota, on small hand-computed examples (the rule in emulator/runtime/backend.py,
from ExecutionContext, BuildContexts, ExecuteCommand and CallFunction, decompiled 1.21)."""
from __future__ import annotations

import pytest

from tests.vm.helpers import SETUP, emulator_for

FUNCTIONS = {
    "t:setup": SETUP + "scoreboard players set #one o 1",
    "t:plain3": "scoreboard players set #a o 1\nscoreboard players set #b o 1\nscoreboard players set #c o 1",
    "t:if_pass": "execute if score #one o matches 1 run scoreboard players set #b o 1",
    "t:if_fail": "execute if score #u o matches 1 run scoreboard players set #b o 1",
    "t:two_stages_fail": "execute if score #u o matches 1 if score #u o matches 2 run say x",
    "t:final_condition": "execute if score #one o matches 1",
    "t:call_g": "function t:g",
    "t:g": "scoreboard players set #a o 1\nscoreboard players set #b o 1",
    "t:ret": "return 1",
    "t:ret_run": "return run scoreboard players set #a o 2",
    "t:if_function": "execute if function t:ret run scoreboard players set #a o 1",
    "t:store_call": "execute store result score #r o run function t:ret",
    "t:tag": "function #t:both",
    "t:say": "say hi",
}


@pytest.mark.parametrize("function, cost", [
    ("t:plain3", 1 + 3),            # CallFunction + one per command
    ("t:if_pass", 1 + 1 + 1),       # + the if stage + the run
    ("t:if_fail", 1 + 1),           # the stage is charged even with no context left
    ("t:two_stages_fail", 1 + 2),   # every stage is charged, once
    ("t:final_condition", 1 + 1),   # a condition ending the chain is the command itself
    ("t:call_g", 1 + 1 + 2),        # `function` costs only its CallFunction
    ("t:ret", 1),                   # return N costs nothing
    ("t:ret_run", 1 + 1),
    ("t:if_function", 1 + 1 + 1),   # if function: no stage charge; its call; the run
    ("t:store_call", 1 + 1 + 1),    # store stage + call
    ("t:tag", 1 + (1 + 2) + (1 + 3)),  # each tag member is a call
    ("t:say", 1 + 1),
])
def test_costs(tmp_path, function, cost):
    emu = emulator_for(tmp_path, FUNCTIONS, tags={"t:both": ["t:g", "t:plain3"]})
    emu.call("t:setup")
    result = emu.runtime.call(function)
    assert (result.cost, result.cut) == (cost, False)
    # the per-line counters hold everything but the two roots' own CallFunction charges
    assert sum(emu.profile.lines.values()) == emu.runtime.commands_outside_ticks - 2


def test_quota_cut_location_and_log(tmp_path):
    body = "".join("scoreboard players add #n o 1\n" for _ in range(20))
    emu = emulator_for(tmp_path, {"t:setup": SETUP, "t:f": body})
    emu.call("t:setup")
    emu.state.gamerules.set("maxCommandChainLength", "10")
    result = emu.runtime.call("t:f")
    # the call costs 1, then 9 adds run; the 10th meets an empty quota
    assert (result.cost, result.cut) == (10, True)
    assert emu.score("#n", "o") == 9
    assert emu.log[-1].text == "Command execution stopped due to limit (executed 10 commands)"
    [diag] = emu.diagnostics
    assert [(f.function, f.loc.line) for f in diag.frames] == [("t:f", 10)]


def test_stage_charges_can_overdraw_the_quota(tmp_path):
    chain = "execute if score #one o matches 1 if score #one o matches 1 if score #one o matches 1 run "
    emu = emulator_for(tmp_path, {"t:setup": FUNCTIONS["t:setup"], "t:f": chain + "scoreboard players add #n o 1"})
    emu.call("t:setup")
    emu.state.gamerules.set("max_command_sequence_length", "3")  # 1.21.11 name, same rule
    result = emu.runtime.call("t:f")
    # call: 3 -> 2; the entry check passes, 3 stages: 2 -> -1; the run's entry check cuts
    assert (result.cost, result.cut) == (4, True)
    assert emu.score("#n", "o") is None


def test_cut_in_nested_function_reports_each_frame(tmp_path):
    functions = {"t:setup": SETUP, "t:outer": "say a\nfunction t:inner",
                 "t:inner": "scoreboard players add #n o 1\nscoreboard players add #n o 1"}
    emu = emulator_for(tmp_path, functions)
    emu.call("t:setup")
    emu.state.gamerules.set("maxCommandChainLength", "4")
    result = emu.runtime.call("t:outer")  # 1 + say 1 + call 1 + add 1, then cut
    assert (result.cost, result.cut, emu.score("#n", "o")) == (4, True, 1)
    [diag] = emu.diagnostics
    assert [(f.function, f.loc.line) for f in diag.frames] == [("t:outer", 2), ("t:inner", 2)]


@pytest.mark.parametrize("stage", ["if score #one o matches 1", "positioned 0 0 0", "store result score #s o"])
def test_fork_limit(tmp_path, stage):
    # BuildContexts: a stage fails the command when the contexts it makes reach maxCommandForkCount
    emu = emulator_for(tmp_path, {"t:setup": FUNCTIONS["t:setup"],
                                  "t:f": f"execute {stage} run scoreboard players set #x o 1\nscoreboard players set #y o 1"})
    emu.call("t:setup")
    emu.state.gamerules.set("maxCommandForkCount", "1")
    emu.call("t:f")
    assert (emu.score("#x", "o"), emu.score("#y", "o")) == (None, 1)
    assert [d.message for d in emu.diagnostics] == ["Maximum number of contexts (1) reached"]
    emu.state.gamerules.set("maxCommandForkCount", "2")
    emu.call("t:f")
    assert emu.score("#x", "o") == 1


def test_if_function_on_empty_tag_ends_the_chain_without_charges(tmp_path):
    # scheduleFunctionConditionsAndTest: no functions, no continuation (not even for 0 contexts)
    emu = emulator_for(tmp_path, {"t:setup": FUNCTIONS["t:setup"],
                                  "t:f": "execute if score #u o matches 1 if function #t:empty if score #one o matches 1 "
                                         "run say never"}, tags={"t:empty": []})
    emu.call("t:setup")
    result = emu.runtime.call("t:f")
    assert result.cost == 1 + 1  # the call and the first stage; nothing after the empty tag


@pytest.mark.parametrize("body, cut, result", [
    ("scoreboard players set #a o 1\nscoreboard players set #b o 1\nreturn 7", True, None),  # return never reached
    ("scoreboard players set #a o 1\nscoreboard players set #b o 1", True, None),  # cut logged with nothing left
    ("scoreboard players set #a o 1\nreturn 7", False, 7),
    ("execute if score #one o matches 1 run return 7", False, 7),  # the return runs inside the charged entry
])
def test_quota_checked_before_every_entry(tmp_path, body, cut, result):
    # ExecutionContext.runCommandQueue checks `commandQuota <= 0` before polling each entry
    emu = emulator_for(tmp_path, {"t:setup": FUNCTIONS["t:setup"], "t:f": body})
    emu.call("t:setup")
    emu.state.gamerules.set("maxCommandChainLength", "3")
    root = emu.runtime.call("t:f")
    assert (root.cut, root.result) == (cut, result)
    assert any("stopped due to limit" in d.message for d in emu.diagnostics) == cut


def test_failing_stage_stops_charging(tmp_path):
    # BuildContexts: a non-forked modifier error returns at once; the later stages are not charged
    emu = emulator_for(tmp_path, {"t:setup": FUNCTIONS["t:setup"],
                                  "t:f": "execute store result score @s o positioned 0 0 0 align xyz run say x"})
    emu.call("t:setup")
    assert emu.runtime.call("t:f").cost == 1 + 1
    assert emu.log == []
