"""The reference backend on its own: command costs, quota, recursion, tags, macros, schedule, log,
sanitizer and runtime diagnostics. Costs are hand-computed from the rule in emulator/runtime/backend.py
(ExecutionContext, BuildContexts, ExecuteCommand, CallFunction of the decompiled 1.21 sources)."""
from __future__ import annotations

import pytest

from emulator.reference import ReferenceBackend
from emulator.world.state import WorldState
from mcfunction_parser.pack.loader import load_packs
from tests.backends.programs import run_root, write_pack

SETUP = "scoreboard objectives add o dummy\n"


def run(tmp_path, functions, entry="t:main", tags=None, sanitize=False, state=None):
    pack = write_pack(tmp_path / "pack", functions, tags)
    state = state or WorldState()
    packs = load_packs([pack])
    assert not [d for d in packs.diagnostics if d.severity == "error"], [d.format() for d in packs.diagnostics]
    backend = ReferenceBackend()
    backend.load(packs, state, sanitize=sanitize)
    return backend, state, backend.run_root(entry)


def scores(state):
    return state.scoreboard.scores().get("o", {})


# ----------------------------------------------------------------------------- costs

@pytest.mark.parametrize("body, cost", [
    # CallFunction 1 + one command 1
    ("scoreboard players set #a o 1", 1 + 1),
    # `return` is a custom executor: only the CallFunction costs
    ("return 1", 1),
    # a redirect stage costs 1 once, the final command 1 per source; `run` is free
    ("execute positioned 1 2 3 run scoreboard players set #a o 1", 1 + 2),
    ("execute positioned 1 2 3 align xyz anchored eyes run scoreboard players set #a o 1", 1 + 4),
    # a failing condition stage still costs; later stages are charged with 0 sources
    ("execute if score #u o matches 1 positioned 0 0 0 run scoreboard players set #a o 1", 1 + 2),
    # a condition as final command: 1 per source
    ("execute if score #u o matches 1", 1 + 1),
    # `as` a selector that finds nothing: the stage costs 1, nothing runs
    ("execute as @e run scoreboard players set #a o 1", 1 + 1),
    # function: only CallFunction entries cost (1 for main, 1 for f, 2 for f's commands)
    ("function t:f", 1 + 1 + 2),
    # return run is free; the command it runs costs 1
    ("return run scoreboard players set #a o 3", 1 + 1),
    # if function: the stage is free, f's call and commands cost, then the final command
    ("execute if function t:f run scoreboard players set #a o 1", 1 + 3),
    ("execute unless function t:f run scoreboard players set #a o 1", 1 + 3 + 1),
    # store stage 1, CallFunction 1, f 2
    ("execute store result score #r o run function t:f", 1 + 1 + 3),
])
def test_costs(tmp_path, body, cost):
    _, _, result = run(tmp_path, {"t:main": body, "t:f": "scoreboard players add #f o 1\nscoreboard players add #f o 1"},
                       state=_with_objective())
    assert result.cost == cost


def _with_objective() -> WorldState:
    state = WorldState()
    state.scoreboard.add_objective("o")
    return state


def test_function_tag_runs_members_in_order_and_sums_returns(tmp_path):
    functions = {
        "t:main": SETUP + "execute store result score #r o run function #t:all",
        "t:a": "scoreboard players set #order o 1\nreturn 2",
        "t:b": "scoreboard players operation #order o *= #ten o\nreturn 3",
        "t:c": "scoreboard players add #order o 5",
    }
    state = _with_objective()
    state.scoreboard.set("#ten", "o", 10)
    _, state, result = run(tmp_path, functions, tags={"t:all": ["t:a", "t:b", "t:c"]}, state=state)
    # FunctionCommand's Accumulator: the sum of the members' returns (c never returns)
    assert scores(state)["#r"] == 5
    assert scores(state)["#order"] == 15
    # main 1 + add 1 + store 1 + 3 CallFunctions + a:1 + b:1 + c:1
    assert result.cost == 9


def test_empty_tag_fails_the_command(tmp_path):
    functions = {"t:main": SETUP + "execute store success score #s o run function #t:none"}
    _, state, _ = run(tmp_path, functions, tags={"t:none": []})
    assert scores(state)["#s"] == 0


# ----------------------------------------------------------------------------- quota and depth

def test_quota_cut_stops_the_root_and_says_where(tmp_path):
    state = WorldState()
    state.gamerules.set("maxCommandChainLength", "5")
    body = SETUP + "\n".join(f"scoreboard players add #a o {i}" for i in range(1, 9))
    _, state, result = run(tmp_path, {"t:main": body}, state=state)
    # CallFunction + objectives add + 3 adds = 5; the 4th add is where it stopped
    assert result.cut and result.cost == 5
    assert scores(state)["#a"] == 1 + 2 + 3
    assert state.log[-1].text == "Command execution stopped due to limit (executed 5 commands)"
    where = state.diagnostics[-1].frames[-1]
    assert (where.function, where.loc.line) == ("t:main", 5)


def test_stage_charges_can_overrun_the_quota(tmp_path):
    # BuildContexts charges every stage without checking: quota 2 and a 3-stage chain
    state = WorldState()
    state.gamerules.set("maxCommandChainLength", "2")
    _, _, result = run(tmp_path, {"t:main": "execute align x align y align z run say hi"}, state=state)
    assert result.cut and result.cost == 4


def test_recursion_100000_deep(tmp_path):
    state = _with_objective()
    state.gamerules.set("maxCommandChainLength", "1000000")
    state.scoreboard.set("#n", "o", 100_000)
    body = "scoreboard players remove #n o 1\nexecute if score #n o matches 1.. run function t:main\nscoreboard players add #back o 1"
    _, state, result = run(tmp_path, {"t:main": body}, state=state)
    assert scores(state)["#n"] == 0 and scores(state)["#back"] == 100_000
    assert result.cost == 100_000 * 4 and not result.cut


# ----------------------------------------------------------------------------- macros

def test_macro_arguments_substituted_and_parsed(tmp_path):
    functions = {
        "t:main": SETUP + 'function t:m {v:7, who:"#x", f:1.5f}\nfunction t:m {v:-2, who:"#y", f:2.0f}',
        "t:m": "$scoreboard players set $(who) o $(v)\n$say $(f)",
    }
    _, state, _ = run(tmp_path, functions)
    assert scores(state) == {"#x": 7, "#y": -2}
    # MacroFunction.stringify: floats through DecimalFormat("#", 15 fraction digits)
    assert [e.text for e in state.log] == ["[Server] 1.5", "[Server] 2"]


def test_macro_missing_key_is_a_diagnostic(tmp_path):
    functions = {
        "t:main": SETUP + "execute store success score #s o run function t:m {other:1}\nscoreboard players set #next o 1",
        "t:m": "$scoreboard players set #a o $(v)",
    }
    _, state, _ = run(tmp_path, functions)
    assert scores(state) == {"#s": 0, "#next": 1}
    (diag,) = state.diagnostics
    assert "Missing argument v to function t:m" in diag.message
    assert [(f.function, f.loc.line) for f in diag.frames] == [("t:main", 2)]


def test_macro_with_storage(tmp_path):
    from mcfunction_parser.nbt import Compound, Int

    state = WorldState()
    state.storage["t:args"] = Compound({"v": Int(12)})
    functions = {"t:main": SETUP + "function t:m with storage t:args", "t:m": "$scoreboard players set #a o $(v)"}
    _, state, _ = run(tmp_path, functions, state=state)
    assert scores(state) == {"#a": 12}


# ----------------------------------------------------------------------------- other commands

def test_schedule_log_and_gamerule(tmp_path):
    functions = {
        "t:main": SETUP + "schedule function t:later 3t\nschedule function t:later 5t append\n"
                          'say hello\ntellraw @a {"text":"hi"}\ngamerule maxCommandChainLength 77\n'
                          "execute store result score #g o run gamerule maxCommandChainLength",
        "t:later": "say later",
    }
    _, state, _ = run(tmp_path, functions)
    assert [(e.due, e.function) for e in state.schedule.pending()] == [(3, "t:later"), (5, "t:later")]
    # no player is online: tellraw finds no receiver and fails (TellRawCommand), so only say logs
    assert [(e.kind, e.text) for e in state.log] == [("say", "[Server] hello")]
    assert state.gamerules.max_command_chain_length == 77
    assert scores(state)["#g"] == 77


@pytest.mark.parametrize("rule, value", [("naturalRegeneration", 1), ("doMobSpawning", 1), ("disableRaids", 0),
                                         ("spawnRadius", 10), ("playersSleepingPercentage", 100)])
def test_every_game_rule_has_its_default(tmp_path, rule, value):
    # GameRules.register (1.21.3, 1.21.7; 1.21.10's command tree for its rules): a query's result is
    # the default, a boolean as 1 or 0
    functions = {"t:main": SETUP + f"execute store result score #g o run gamerule {rule}"}
    _, state, _ = run(tmp_path, functions)
    assert scores(state)["#g"] == value and not state.diagnostics


def test_a_1_21_11_name_reads_the_rule_it_renamed():
    # natural_health_regeneration is naturalRegeneration renamed (GameRules of 26.1); raids, which
    # replaced disableRaids with the opposite meaning, is a rule of its own
    rules = WorldState().gamerules
    rules.set("natural_health_regeneration", "false")
    assert rules.get("naturalRegeneration") == "false"
    assert (rules.get("raids"), rules.get("disableRaids")) == ("true", "false")


def test_objectives_and_wildcard(tmp_path):
    body = ("scoreboard objectives add o dummy\nscoreboard objectives add p dummy\n"
            "execute store result score #n o run scoreboard objectives add q dummy\n"
            "scoreboard players set #a p 1\nscoreboard players set #b o 2\n"
            "scoreboard players add * p 10\n"
            "execute store success score #dup o run scoreboard objectives add o dummy\n"
            "scoreboard objectives remove q")
    _, state, _ = run(tmp_path, {"t:main": body})
    all_scores = state.scoreboard.scores()
    # `*` is every holder with any score (Scoreboard.getTrackedPlayers), here #n, #a, #b
    assert all_scores["p"] == {"#a": 11, "#n": 10, "#b": 10}
    assert all_scores["o"] == {"#n": 3, "#b": 2, "#dup": 0}
    assert "q" not in all_scores


def test_selector_holder_without_entities_fails(tmp_path):
    body = SETUP + "execute store success score #s o run scoreboard players set @s o 1"
    _, state, _ = run(tmp_path, {"t:main": body})
    assert scores(state) == {"#s": 0}


def test_unknown_function_and_unsupported_command_are_diagnostics(tmp_path):
    body = SETUP + "function t:missing\nlocate biome minecraft:plains\nlocate biome minecraft:plains\nscoreboard players set #ok o 1"
    _, state, result = run(tmp_path, {"t:main": body})
    assert scores(state) == {"#ok": 1}
    messages = [d.message for d in state.diagnostics]
    assert messages[0] == "Unknown function t:missing"
    assert len(messages) == 3 and "not emulated" in messages[1] and "not emulated" in messages[2]


def test_unknown_root_function(tmp_path):
    _, state, result = run(tmp_path, {"t:main": "say x"}, entry="t:nope")
    assert result.cost == 0 and result.result is None
    assert state.diagnostics[0].message == "Unknown function t:nope"


# ----------------------------------------------------------------------------- sanitizer

def test_sanitizer_reports_wrapping_results(tmp_path):
    body = (SETUP + "scoreboard players set #a o 2147483647\nscoreboard players add #a o 1\n"
            "scoreboard players set #b o 65536\nscoreboard players operation #b o *= #b o\n"
            "scoreboard players set #c o 5\nscoreboard players operation #c o += #c o")
    pack = write_pack(tmp_path / "pack", {"t:main": body})
    outcome = run_root("python", pack, "t:main", sanitize=True)
    assert outcome.overflows == (
        ("t:main", 3, "add", 2147483647, 1, 2147483648, -2147483648),
        ("t:main", 5, "*=", 65536, 65536, 2**32, 0),
    )
    assert run_root("python", pack, "t:main").overflows == ()


# ----------------------------------------------------------------------------- storage data

def test_storage_data_commands(tmp_path):
    body = (SETUP + "data merge storage t:s {a:1.5d, list:[1,2], name:\"héllo\"}\n"
            "data modify storage t:s list append value 3\n"
            "execute store result score #len o run data get storage t:s list\n"
            "execute store result score #name o run data get storage t:s name\n"
            # DataCommands.getNumeric: Mth.floor(value * scale)
            "execute store result score #a o run data get storage t:s a 10\n"
            "execute store result score #neg o run data get storage t:s a -1\n"
            # ExecuteCommand.storeData: (int)(result * scale) truncates toward zero and saturates
            "scoreboard players set #big o 1000000000\n"
            "execute store result storage t:s big int 1000 run scoreboard players get #big o\n"
            "execute store result storage t:s half int 0.5 run scoreboard players set #m o -3\n"
            "execute store result score #stored o run data get storage t:s big\n"
            "execute store result score #half o run data get storage t:s half\n"
            "execute store success score #has o if data storage t:s list[{}]\n"
            "execute store result score #count o if data storage t:s list[]\n"
            "execute store success score #nothing o run data remove storage t:s missing\n"
            "function t:m with storage t:s")
    functions = {"t:main": body, "t:m": "$scoreboard players set #from_macro o $(half)"}
    _, state, _ = run(tmp_path, functions)
    assert scores(state) == {
        "#len": 3, "#name": 5, "#a": 15, "#neg": -2, "#big": 1000000000, "#m": -3,
        "#stored": 2147483647, "#half": -1, "#has": 0, "#count": 3, "#nothing": 0, "#from_macro": -1,
    }


def test_fork_limit(tmp_path):
    # BuildContexts: a stage reaching maxCommandForkCount contexts fails the whole command
    state = _with_objective()
    state.gamerules.set("maxCommandForkCount", "1")
    _, state, result = run(tmp_path, {"t:main": "execute positioned 0 0 0 run scoreboard players set #a o 1"}, state=state)
    assert scores(state) == {}
    assert state.diagnostics[0].message == "Maximum number of contexts (1) reached"
    assert result.cost == 2


def test_an_internal_error_is_a_diagnostic_and_the_run_goes_on(tmp_path, monkeypatch):
    from emulator.commands import dispatch
    from mcfunction_parser import ast

    def broken(*args):
        raise RuntimeError("boom")

    monkeypatch.setitem(dispatch.HANDLERS, ast.Say, broken)
    _, state, result = run(tmp_path, {"t:main": SETUP + "say x\nscoreboard players set #after o 1"})
    assert scores(state) == {"#after": 1}
    (diag,) = state.diagnostics
    assert diag.message == "internal error in the reference backend: RuntimeError: boom"
    assert [(f.function, f.loc.line) for f in diag.frames] == [("t:main", 2)]


def test_context_modifiers_move_the_source(tmp_path):
    # positions and rotations come from the world library's game math; the checks here are the
    # ones with exact answers: centring of integer x/z, local coordinates at yaw 90 (facing -x),
    # align flooring, and the nether's coordinate scale of 8
    from emulator.commands.env import Env
    from emulator.commands.stages import stage
    from emulator.world.context import Context
    from emulator.world.state import WorldState
    from mcfunction_parser.diagnostics import Loc
    from mcfunction_parser.parse import parse_command

    env = Env(WorldState(), {}, set())

    def where(text):
        command, _ = parse_command(f"execute {text} run say x", Loc("x", 1, 1))
        context = Context(pos=(8.0, 64.0, 16.0))
        for sub in command.subcommands:
            (context,) = stage(env, sub, context)
        return context

    assert where("positioned 1 2 3").pos == (1.5, 2.0, 3.5)
    assert where("rotated 90 0 positioned ^ ^ ^1").pos == (7.0, 64.0, 16.0)
    assert where("positioned 0.7 1.2 -0.5 align xz").pos == (0.0, 1.2, -1.0)
    assert where("in minecraft:the_nether").pos == (1.0, 64.0, 2.0)
    assert where("rotated ~10 ~-5").rot == (10.0, -5.0)


def test_wildcard_is_no_single_holder(tmp_path):
    # ScoreHolderArgument.getName passes an empty default for '*': `get *` and `if score *` fail
    body = (SETUP + "scoreboard players set #a o 1\n"
            "execute store success score #g o run scoreboard players get * o\n"
            "execute store success score #i o if score * o matches 1")
    _, state, _ = run(tmp_path, {"t:main": body})
    assert scores(state) == {"#a": 1, "#g": 0, "#i": 0}


@pytest.mark.parametrize("value, text", [
    # MacroFunction.stringify: DecimalFormat("#") with 15 fraction digits, HALF_EVEN, US symbols;
    # a float tag goes through (double) of its float32 value
    ("0.1f", "0.100000001490116"), ("0.1d", "0.1"), ("2.0d", "2"), ("1e20d", "100000000000000000000"),
    ("1e-20d", "0"), ("-3b", "-3"), ("7", "7"), ('"hi"', "hi"), ("{a:1b}", "{a:1b}"),
])
def test_macro_values_are_stringified_as_the_game(value, text):
    from emulator.runtime.macros import stringify
    from mcfunction_parser.diagnostics import Loc
    from mcfunction_parser.reader import Reader
    from mcfunction_parser.snbt import compound

    parsed = compound(Reader("{v:" + value + "}", Loc("x", 1, 1), (1, 21, 0)))["v"]
    assert stringify(parsed) == text
