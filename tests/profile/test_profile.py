"""``dpemu profile``: every format, backends agreeing, stacks, the trace format, baselines."""
import json
import re
from pathlib import Path

import pytest
from click.testing import CliRunner

from emulator.cli import main
from emulator.profile.formats import compare, parse_collapsed

DATAPACK = Path(__file__).resolve().parents[2] / "datapack"
# the pool pack's break (README, "Profiling packs"): load, table, full-power shot, then its first ticks
BREAK = ("--call", "pool:table/setup", "--call", "pool:api/shot {angle:0,speed:6500,tip_x:0,tip_y:0,elevation:0}",
         "--ticks", 5)
# a folded stack as flamegraph.pl and speedscope read it: frames joined by ';', a space, a count
FOLDED = re.compile(r"[^;\s]+(?:;[^;\s]+)* [1-9][0-9]*")

# main calls a twice and b once; both call the shared leaf f, so f has two distinct stacks
FUNCTIONS = {
    "demo/function/main.mcfunction": "scoreboard players set $x o 1\nfunction demo:a\nfunction demo:a\n"
                                     "function demo:b\n"
                                     "execute if score $x o matches 1.. run scoreboard players add $y o 1\n",
    "demo/function/a.mcfunction": "scoreboard players add $x o 2\nfunction demo:f\n",
    "demo/function/b.mcfunction": "function demo:f\nsay hello\n",
    "demo/function/f.mcfunction": "scoreboard players add $x o 1\nscoreboard players add $x o 1\n",
    "demo/function/init.mcfunction": "scoreboard objectives add o dummy\n",
    "demo/function/tick.mcfunction": "scoreboard players add $t o 1\n"
                                     "execute if score $t o matches 2 run function demo:main\n",
}


@pytest.fixture
def demo(pack):
    return pack(FUNCTIONS, load=["demo:init"], tick=["demo:tick"])


def profile(*args):
    result = CliRunner().invoke(main, ["profile", *map(str, args)])
    return result


def report(root, *args):
    result = profile(root, "--format", "json", *args)
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)  # diagnostics go to stderr


@pytest.mark.parametrize("args", [(), ("--call", "demo:main")])
def test_backends_agree_on_every_count(demo, args):
    numba = report(demo, "--ticks", 3, *args)
    python = report(demo, "--ticks", 3, "--backend", "python", *args)
    for key in ("commands", "ticks", "roots", "functions"):
        assert numba[key] == python[key], key
    assert [(x["path"], x["line"], x["commands"]) for x in numba["lines"]] == \
           [(x["path"], x["line"], x["commands"]) for x in python["lines"]]


def test_counts_per_tick_root_function_and_line(demo):
    r = report(demo, "--ticks", 3)
    # the load (call 1 + 1 command) runs before the first tick; tick 1: tick (call 1 + 1 command
    # + 1 failed condition stage); tick 2 also calls main (1) from the tick's execute line;
    # main's body: set 1, a twice
    # (call 1 + add 1 + call f 1 + f's 2), b (call 1 + call f 1 + f's 2 + say 1), execute 1 + 1
    main_body = 1 + 2 * (1 + 1 + 1 + 2) + (1 + 1 + 2 + 1) + 2
    assert r["ticks"]["series"] == [3, 3 + 1 + main_body, 3]
    assert r["outside_ticks"] == {"load": 2, "setup": 0}
    assert r["commands"] == sum(r["ticks"]["series"]) + 2
    assert r["ticks"]["max"] == 4 + main_body and r["ticks"]["mean"] == pytest.approx((r["commands"] - 2) / 3)
    roots = {x["function"]: x for x in r["roots"]}
    assert roots["demo:tick"]["runs"] == 3 and roots["demo:tick"]["max_cost"] == 4 + main_body
    assert roots["demo:tick"]["headroom"] == 65536 - 4 - main_body
    functions = {f["function"]: f for f in r["functions"]}
    assert functions["demo:f"] == {"function": "demo:f", "self": 6, "total": 6, "calls": 3}
    assert functions["demo:a"]["calls"] == 2 and functions["demo:a"]["total"] == 2 * (2 + 2)
    lines = {(x["path"].rsplit("/", 1)[-1], x["line"]): x for x in r["lines"]}
    assert lines[("f.mcfunction", 1)]["commands"] == 3
    assert lines[("main.mcfunction", 5)]["source"] == \
        "execute if score $x o matches 1.. run scoreboard players add $y o 1"
    # one VM instruction for the condition, one for the final command
    assert [i["count"] for i in lines[("main.mcfunction", 5)]["instructions"]] == [1, 1]


def test_host_commands_are_listed_with_counts(demo):
    host = report(demo, "--ticks", 3)["host"]
    say = [h for h in host if h["command"] == "say hello"]
    assert say and say[0]["count"] == 1 and say[0]["function"] == "demo:b" and say[0]["line"] == 2


# a tick whose stores and teleport only Python can do: a store into an entity's Air (the VM stores
# only the fields its table keeps) and a teleport facing a random entity; a store is never charged,
# so only the backend's record of host runs can list it
HOST_ONLY = {
    "demo/function/init.mcfunction": "scoreboard objectives add o dummy\nsummon marker\nsummon marker\n",
    "demo/function/tick.mcfunction": "execute as @e[type=marker] store result entity @s Air short 1 "
                                     "run scoreboard players add $t o 1\n"
                                     "execute as @e[type=marker] run tp @s ^ ^ ^1 facing entity "
                                     "@e[type=marker,sort=random,limit=1] feet\n",
}


def test_host_run_stores_and_teleports_are_listed_with_their_runs(pack):
    root = pack(HOST_ONLY, load=["demo:init"], tick=["demo:tick"])
    host = report(root, "--ticks", 3)["host"]
    by_kind = {(h["line"], h["op"]): h for h in host if h["function"] == "demo:tick"}
    # 2 markers x 3 ticks: the store runs after each add, the teleport once per marker
    store = by_kind[(1, "store")]
    assert store["count"] == 6 and store["function"] == "demo:tick" and store["path"].endswith("tick.mcfunction")
    assert store["command"].startswith("execute as @e[type=marker] store result entity @s Air")
    assert by_kind[(2, "command")]["count"] == 6 and by_kind[(2, "command")]["command"].endswith("limit=1] feet")
    assert not [h for h in host if h["function"] == "demo:init"]  # the load's summons are not listed
    table = profile(root, "--ticks", 3).output
    assert "host-executed commands (" in table
    assert re.search(r"^\s+6  demo:tick  \S+tick\.mcfunction:1  store  execute as", table, re.M)


def test_a_tick_without_host_ops_lists_none(pack):
    # the load's host commands (objectives add, summon) are not listed; a --call's are (the tick's
    # selector makes the program the whole loop's, which runs objective commands itself: a small
    # loop's program hands them to the host, emulator.vm.variants.TO_HOST)
    root = pack({**HOST_ONLY, "demo/function/tick.mcfunction": "execute as @e run scoreboard players add $t o 1\n"},
                load=["demo:init"], tick=["demo:tick"])
    assert report(root, "--ticks", 3)["host"] == []
    assert "host-executed commands: none" in profile(root, "--ticks", 3).output
    called = report(root, "--ticks", 1, "--call", "demo:init")["host"]
    # the objective exists by then: the VM fails its add itself
    assert [(h["line"], h["op"], h["count"]) for h in called] == [(2, "command", 1), (3, "command", 1)]


def test_host_ops_of_macro_instances_count_on_their_line(pack):
    # each instance of a macro line is a function of its own in the VM: the list counts them together
    root = pack({"demo/function/tick.mcfunction": 'function demo:mark {t:"a"}\nfunction demo:mark {t:"b"}\n',
                 "demo/function/mark.mcfunction": '$summon marker ~ ~ ~ {Tags:["$(t)"]}\n'}, tick=["demo:tick"])
    host = report(root, "--ticks", 2)["host"]
    assert [(h["function"], h["line"], h["op"], h["count"]) for h in host] == [("demo:mark", 1, "command", 4)]


def test_collapsed_stacks_add_up_to_the_command_count(demo):
    result = profile(demo, "--ticks", 3, "--format", "collapsed")
    assert result.exit_code == 0, result.output
    stacks = parse_collapsed(result.output)
    assert sum(stacks.values()) == report(demo, "--ticks", 3)["commands"]
    # the leaf's cost is split by caller
    assert stacks["demo:tick;demo:main;demo:a;demo:f"] == 4
    assert stacks["demo:tick;demo:main;demo:b;demo:f"] == 2
    assert all(" " not in stack for stack in stacks)


def test_a_stage_after_if_function_is_charged_in_its_own_function(pack):
    # f's line 2 calls f again; the inner f's condition fails, so it returns nothing, the outer
    # ``if function`` passes no source, and the outer ``as`` stage is charged in the outer f
    root = pack({"demo/function/main.mcfunction": "scoreboard objectives add o dummy\nfunction demo:f\n",
                 "demo/function/f.mcfunction": "scoreboard players add #n o 1\n"
                                               "execute if score #n o matches ..1 if function demo:f as @e run say x\n"})
    result = profile(root, "--ticks", 0, "--call", "demo:main", "--format", "collapsed")
    assert result.exit_code == 0, result.output
    # main: its call, 2 commands; the outer f: add, condition, the call of f, ``as``; the inner f:
    # add, condition, ``as``
    assert parse_collapsed(result.output) == {"demo:main": 3, "demo:main;demo:f": 4, "demo:main;demo:f;demo:f": 3}


def test_collapsed_needs_the_python_backend(demo):
    result = profile(demo, "--format", "collapsed", "--backend", "numba")
    assert result.exit_code == 2 and "only --backend python" in result.output


def test_trace_matches_the_debug_function_format(pack):
    root = pack({"demo/function/main.mcfunction": "scoreboard objectives add o dummy\nscoreboard players set $x o 1\n"
                                                  "function demo:sub\nexecute if score $x o matches 5 run say no\n",
                 "demo/function/sub.mcfunction": "scoreboard players add $x o 2\n"})
    result = profile(root, "--ticks", 0, "--call", "demo:main", "--format", "trace")
    assert result.exit_code == 0, result.output
    # DebugCommand.Tracer: 4 spaces per depth + 1; " -> N" after a command's result
    assert result.output == (
        "demo:main\n"
        "    [F] demo:main size=4\n"
        "        [C] scoreboard objectives add o dummy -> 1\n"
        "        [C] scoreboard players set $x o 1 -> 1\n"
        "        [C] function demo:sub\n"
        "        [F] demo:sub size=1\n"
        "            [C] scoreboard players add $x o 2 -> 3\n"
        "        [C] execute if score $x o matches 5 run say no\n"
    )


def test_table_format(demo):
    result = profile(demo, "--ticks", 3, "--top", 3)
    assert result.exit_code == 0, result.output
    text = result.output
    assert text.startswith("backend numba: ") and "roots (quota 65536 each):" in text
    assert "functions (top 3 by total):" in text and "hot lines (top 3):" in text and "say hello" in text


def test_quota_cut_shows_in_the_roots(pack):
    root = pack({"demo/function/init.mcfunction": "gamerule maxCommandChainLength 5\n",
                 "demo/function/loop.mcfunction": "function demo:loop\n"}, load=["demo:init"], tick=["demo:loop"])
    roots = {r["function"]: r for r in report(root, "--ticks", 2)["roots"]}
    assert roots["demo:loop"]["cut"] == 2 and roots["demo:loop"]["headroom"] <= 0


def test_baseline_comparison(demo, tmp_path):
    saved = tmp_path / "base.json"
    assert profile(demo, "--ticks", 3, "--format", "json", "-o", saved).exit_code == 0
    same = profile(demo, "--ticks", 3, "--baseline", saved)
    assert same.exit_code == 0 and "no function grew more than 10%" in same.output
    data = json.loads(saved.read_text())
    for f in data["functions"]:
        if f["function"] == "demo:f":
            f["total"] = 5  # now 6: +20%
    saved.write_text(json.dumps(data))
    grown = profile(demo, "--ticks", 3, "--baseline", saved)
    assert grown.exit_code == 1 and "regression: demo:f: 5 -> 6 (+20.0%, threshold 10%)" in grown.output
    assert profile(demo, "--ticks", 3, "--baseline", saved, "--threshold", 25).exit_code == 0


def test_missing_or_bad_baseline_is_a_clear_error(demo, tmp_path):
    missing = profile(demo, "--baseline", tmp_path / "nope.json")
    assert missing.exit_code == 2 and "nope.json: no such file" in missing.output
    (tmp_path / "bad.json").write_text("[1]")
    bad = profile(demo, "--baseline", tmp_path / "bad.json")
    assert bad.exit_code == 2 and "not a JSON profile" in bad.output


def test_compare_rules():
    before = {"functions": [{"function": "a", "self": 10, "total": 100}, {"function": "b", "self": 5, "total": None}]}
    after = {"functions": [{"function": "a", "self": 10, "total": 110}, {"function": "b", "self": 6, "total": None},
                           {"function": "c", "self": 1, "total": 1}]}
    assert compare(before, after, 10.0) == ["b: 5 -> 6 (+20.0%, threshold 10%)", "c: 0 -> 1 (new, threshold 10%)"]


def test_trace_of_a_forked_command_puts_later_results_on_their_own_lines(pack):
    root = pack({"demo/function/main.mcfunction": "scoreboard objectives add o dummy\nsummon marker\nsummon marker\n"
                                                  "execute as @e[type=marker] run scoreboard players add $x o 1\n"})
    result = profile(root, "--ticks", 0, "--call", "demo:main", "--format", "trace")
    lines = result.output.splitlines()
    command = "execute as @e[type=marker] run scoreboard players add $x o 1"
    assert lines[-2:] == [f"        [C] {command} -> 1", f"        [R = 2] {command}"]


def test_until_stops_the_run(demo):
    r = report(demo, "--ticks", 50, "--until", "$t o 4")
    assert r["ticks"]["count"] == 4


def test_trace_errors_continue_on_the_same_line_as_in_the_game(pack):
    # DebugCommand.Tracer.onError prints "[E] message" one level deeper and ends no line
    root = pack({"demo/function/main.mcfunction": "scoreboard players set $x nope 1\nsay hi\n"})
    result = profile(root, "--ticks", 0, "--call", "demo:main", "--format", "trace")
    lines = result.output.splitlines()
    assert lines[2] == "        [C] scoreboard players set $x nope 1"
    assert lines[3] == "            [E] Unknown scoreboard objective 'nope'        [C] say hi -> 1"


def test_break_shot_profile_opens_in_a_flame_graph_viewer():
    result = profile(DATAPACK, *BREAK, "--format", "collapsed")
    assert result.exit_code == 0, result.output
    lines = result.output.splitlines()
    assert lines and all(FOLDED.fullmatch(line) for line in lines)
    stacks = parse_collapsed(result.output)
    numba = report(DATAPACK, *BREAK)
    assert sum(stacks.values()) == numba["commands"]
    # the shot was played, not refused for lack of objectives (the load functions ran first):
    # the physics step runs every tick and carries most of the cost
    assert numba["outside_ticks"]["load"] > 0 and min(numba["ticks"]["series"]) > 100
    physics = sum(count for stack, count in stacks.items() if stack.startswith("pool:tick;pool:physics/step"))
    assert physics > 0.9 * sum(numba["ticks"]["series"])
