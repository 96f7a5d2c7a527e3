"""Functions in the VM: calls, tags, return forms, execute if function, macros, deep recursion
(FunctionCommand, ReturnCommand, CallFunction, ExecuteCommand.scheduleFunctionConditionsAndTest,
FallthroughTask in the decompiled 1.21 sources)."""
from __future__ import annotations

import pytest

from mcfunction_parser.nbt import Compound, Int
from emulator import Emulator
from tests.backends.programs import write_pack
from tests.vm.helpers import SETUP, emulator_for, run_main

HELPERS = {
    "t:five": "return 5",
    "t:zero": "return 0",
    "t:failing": "return fail",
    "t:plain": "scoreboard players add #plain o 1",
    "t:ret_run": "return run scoreboard players set #x o 9",
    "t:ret_run_dead": "scoreboard players set #u o 0\nreturn run execute if score #u o matches 1 run say no",
}


@pytest.mark.parametrize("call, expected", [
    ("t:five", 5), ("t:zero", 0), ("t:failing", 0), ("t:plain", None), ("t:ret_run", 9),
    ("t:ret_run_dead", 0),  # return run with no context left falls through: return fail
])
def test_return_values(tmp_path, call, expected):
    emu = emulator_for(tmp_path, {"t:main": SETUP, **HELPERS})
    emu.call("t:main")
    assert emu.call(call) == expected


def test_return_stops_the_function(tmp_path):
    emu, result = run_main(tmp_path, "scoreboard players set #a o 1\nreturn 3\nscoreboard players set #a o 2")
    assert (result, emu.score("#a", "o")) == (3, 1)


def test_conditional_return(tmp_path):
    emu, result = run_main(tmp_path, "scoreboard players set #a o 1\n"
                                     "execute if score #a o matches 2 run return 7\n"
                                     "execute if score #a o matches 1 run return 8\nreturn 9")
    assert result == 8


def test_return_run_function_takes_its_value(tmp_path):
    _, result = run_main(tmp_path, "return run function t:five", HELPERS)
    assert result == 5
    _, result = run_main(tmp_path / "b", "return run function t:plain\nreturn 1", HELPERS)
    assert result == 0  # the callee never returned: FallthroughTask, the caller returns fail


@pytest.mark.parametrize("condition, hit", [
    ("if function t:five", True), ("unless function t:five", False),
    ("if function t:zero", False), ("unless function t:zero", True),
    ("if function t:failing", False), ("unless function t:failing", True),
    ("if function t:plain", False), ("unless function t:plain", True),  # no return: value 0
])
def test_execute_if_function(tmp_path, condition, hit):
    emu, _ = run_main(tmp_path, f"execute {condition} run scoreboard players set #hit o 1", HELPERS)
    assert emu.score("#hit", "o") == (1 if hit else None)


def test_return_inside_condition_function_does_not_return_caller(tmp_path):
    emu, result = run_main(tmp_path, "execute if function t:five run scoreboard players set #a o 1\n"
                                     "scoreboard players set #b o 1", HELPERS)
    assert (emu.score("#a", "o"), emu.score("#b", "o"), result) == (1, 1, None)


def test_function_tags_in_order_and_results(tmp_path):
    functions = {
        "t:main": SETUP + "function #t:all\nexecute store result score #sum o run function #t:all\n"
                          "execute if function #t:all run scoreboard players set #any o 1",
        "t:a": "scoreboard players add #n o 1\nscoreboard players operation #trace o *= #ten o\n"
               "scoreboard players add #trace o 1\nreturn 2",
        "t:b": "scoreboard players operation #trace o *= #ten o\nscoreboard players add #trace o 2\nreturn 3",
        "t:c": "scoreboard players operation #trace o *= #ten o\nscoreboard players add #trace o 3",
    }
    emu = emulator_for(tmp_path, functions, tags={"t:all": ["t:a", "t:b", "t:c"]})
    emu.set_score("#ten", "o", 10)
    emu.call("t:main")
    assert emu.score("#sum", "o") == 5  # the sum of the members that returned
    assert emu.score("#any", "o") == 1  # the first member returning 2 decides
    assert emu.score("#n", "o") == 3  # the condition stopped after t:a returned
    assert emu.score("#trace", "o") == 1231231


def test_unknown_function_is_a_diagnostic_with_traceback(tmp_path):
    emu, _ = run_main(tmp_path, "function t:helper\nscoreboard players set #after o 1",
                      {"t:helper": "\n\nfunction t:missing"})
    assert emu.score("#after", "o") == 1
    [diag] = emu.diagnostics
    assert diag.message == "Unknown function t:missing"
    assert [(f.function, f.loc.line) for f in diag.frames] == [("t:main", 2), ("t:helper", 3)]


def test_unknown_root_function(tmp_path):
    emu, _ = run_main(tmp_path, "")
    assert emu.call("t:nothing") is None
    assert "Unknown function t:nothing" in emu.diagnostics[-1].message


def test_macros_substitute_and_cache(tmp_path):
    functions = {
        "t:main": SETUP + "function t:m {v:3}\nfunction t:m {v:4}\nfunction t:m {v:3}\n"
                          "function t:m with storage t:s args",
        "t:m": "$scoreboard players add #sum o $(v)\nscoreboard players add #calls o 1",
    }
    emu = emulator_for(tmp_path, functions)
    emu.state.storage["t:s"] = Compound({"args": Compound({"v": Int(10)})})
    emu.call("t:main")
    assert emu.score("#sum", "o") == 20
    assert emu.score("#calls", "o") == 4
    instances = [f for f in emu.backend.program.functions if f.startswith("t:m#")]
    assert len(instances) == 3  # v=3 compiled once
    assert emu.diagnostics == []


def test_macro_missing_key(tmp_path):
    functions = {"t:main": SETUP + "function t:m {w:1}\nscoreboard players set #after o 1",
                 "t:m": "$scoreboard players add #sum o $(v)"}
    emu = emulator_for(tmp_path, functions)
    emu.call("t:main")
    assert emu.score("#after", "o") == 1 and emu.score("#sum", "o") is None
    [diag] = emu.diagnostics
    assert "Missing argument v" in diag.message
    assert diag.frames[-1].loc.line == 2


def test_recursion_100000_deep(tmp_path):
    functions = {
        "t:main": SETUP + "gamerule maxCommandChainLength 2000000",
        "t:down": "scoreboard players remove #n o 1\nexecute if score #n o matches 1.. run function t:down\n"
                  "scoreboard players add #back o 1",
    }
    emu = emulator_for(tmp_path, functions)
    emu.call("t:main")  # the gamerule applies to later roots
    emu.set_score("#n", "o", 100000)
    emu.call("t:down")
    assert emu.score("#n", "o") == 0
    assert emu.score("#back", "o") == 100000  # every frame resumed after its callee
    assert emu.diagnostics == []


def test_stack_overflow_stops_the_root_cleanly(tmp_path):
    functions = {"t:main": SETUP + "gamerule maxCommandChainLength 2000000",
                 "t:forever": "scoreboard players add #depth o 1\nfunction t:forever"}
    emu = emulator_for(tmp_path, functions)
    emu.call("t:main")
    emu.backend.max_depth = 1000  # the game's cap is 10,000,000 queued entries; smaller to test
    emu.call("t:forever")
    assert emu.score("#depth", "o") == 1000  # 1000 activations fit; the 1001st call stops the root
    [diag] = emu.diagnostics
    assert diag.message == "Command execution stopped due to command queue overflow (max 1000)"
    assert len(diag.frames) == 1000 and diag.frames[-1].loc.line == 2
    emu.call("t:main")  # the next root runs normally
    assert len(emu.diagnostics) == 1


@pytest.mark.parametrize("backend", ["numba", "python"])
@pytest.mark.parametrize("prefix", ["execute rotated as @e[type=armor_stand]", "execute if score #g o matches 1"])
def test_return_run_keeps_the_fork_of_its_chain(tmp_path, backend, prefix):
    # ReturnCommand's rest runs as a BuildContexts.Continuation with the chain's ChainModifiers:
    # after a fork (as, at, if ...) the store stage's error (@s is the server) drops only its
    # context, none is left, and FallthroughTask makes the function return failure (0)
    pack = write_pack(tmp_path / "pack", {"t:main": "scoreboard objectives add o dummy\nscoreboard players set #g o 1\n"
                                                    "summon armor_stand ~ ~ ~\n"
                                                    f"{prefix} run return run execute store result score @s o "
                                                    "run scoreboard players add #a o 1"})
    emu = Emulator(backend=backend)
    emu.load(pack)
    emu.start()
    assert emu.runtime.call("t:main").result == 0


@pytest.mark.parametrize("backend", ["numba", "python"])
@pytest.mark.parametrize("stages, calls, runs", [
    ("as @e if entity @e[tag=m,scores={o=..5}]", 2, 2),
    ("as @e store result score @e[tag=m,scores={o=..5}] o", 2, 2),
    ("as @e[tag=m] at @e[tag=m,scores={o=..5}]", 2, 2),
    ("as @e[tag=m] if function t:mark as @e", 6, 4),  # two calls, then a call per context of the second `as`
])
def test_if_function_runs_after_every_context_passed_the_stages_before(tmp_path, backend, stages, calls, runs):
    # ExecuteCommand.scheduleFunctionConditionsAndTest: the stages before `if function` are applied to
    # every context first (BuildContexts), then the function is queued for each context in turn and
    # the chain goes on with those that passed. t:mark sets every marker's score to 7, so a context
    # whose stages were tested after an earlier context's call would fail them.
    emu, _ = run_main(tmp_path, 'summon marker ~ ~ ~ {Tags:["m"]}\nsummon marker ~ ~ ~ {Tags:["m"]}\n'
                                "scoreboard players set @e[tag=m,limit=1] o 0\n"
                                f"execute {stages} if function t:mark run scoreboard players add #runs o 1",
                      {"t:mark": "scoreboard players set @e[tag=m] o 7\nscoreboard players add #calls o 1\nreturn 1"},
                      backend=backend)
    assert (emu.score("#calls", "o"), emu.score("#runs", "o")) == (calls, runs)
