"""``dpemu run``: setup order, ticking, --until, JSON and CSV outputs, clean errors."""
from __future__ import annotations

import csv
import json

import pytest
from click.testing import CliRunner

from emulator.cli import main
from tests.backends.programs import write_pack

FUNCTIONS = {
    "t:load": "scoreboard objectives add o dummy\nscoreboard players set #step o 10",
    "t:tick": "scoreboard players operation #n o += #step o\nexecute if score #n o matches 30 run say thirty",
    "t:double": "scoreboard players operation #n o += #n o",
    "t:big": "scoreboard players set #m o 2147483647\nscoreboard players add #m o 1",
}
TAGS = {"minecraft:load": ["t:load"], "minecraft:tick": ["t:tick"]}


@pytest.fixture
def pack(tmp_path):
    return str(write_pack(tmp_path / "pack", FUNCTIONS, TAGS))


def invoke(*args):
    result = CliRunner().invoke(main, ["run", *args])
    assert result.exception is None or isinstance(result.exception, SystemExit), result.exception
    return result


def test_json_report(pack, tmp_path):
    out = tmp_path / "r.json"
    result = invoke(pack, "--ticks", "4", "--watch", "#n o", "--json", str(out))
    assert result.exit_code == 0, result.output
    report = json.loads(out.read_text())
    assert {"ticks", "commands", "commands_per_tick", "scores", "log", "overflows", "diagnostics"} <= set(report)
    assert report["ticks"] == 4
    assert report["scores"]["o"]["#n"] == 40
    # the load (call + 2) before the ticks; each tick: call + op + if stage, +1 for say at #n=30
    assert report["commands_per_tick"] == [3, 3, 4, 3]
    assert (report["load_commands"], report["setup_commands"]) == (3, 0)
    assert report["commands"] == sum(report["commands_per_tick"]) + 3
    assert report["log"][0]["text"] == "[Server] thirty" and report["log"][0]["tick"] == 2
    assert report["quota_headroom"] == 65536 - 4
    assert "#n o = 40" in result.output


def test_set_and_call_apply_in_command_line_order(pack, tmp_path):
    out = tmp_path / "r.json"
    invoke(pack, "--ticks", "0", "--set", "#n o 3", "--call", "t:double", "--set", "#k o 1",
           "--call", "t:double", "--json", str(out))
    report = json.loads(out.read_text())
    assert report["scores"]["o"] == {"#step": 10, "#n": 12, "#k": 1}  # (3 * 2) * 2: both calls after the first --set


def test_load_runs_before_set_and_call(pack, tmp_path):
    # as in the game, #minecraft:load runs when the world loads, before any command: t:double
    # finds the objective and #step set, and the first tick runs only #minecraft:tick
    out = tmp_path / "r.json"
    invoke(pack, "--ticks", "1", "--call", "t:double", "--set", "#n o 5", "--call", "t:double", "--json", str(out))
    report = json.loads(out.read_text())
    assert report["diagnostics"] == []
    assert report["scores"]["o"] == {"#step": 10, "#n": 5 * 2 + 10}
    assert report["commands_per_tick"] == [3]
    assert (report["load_commands"], report["setup_commands"]) == (3, 2 * 2)


def test_until_and_csv(pack, tmp_path):
    out = tmp_path / "w.csv"
    result = invoke(pack, "--ticks", "100", "--until", "#n o 25..", "--csv", str(out))
    assert result.exit_code == 0
    rows = list(csv.reader(out.open()))
    assert rows == [["tick", "#n o"], ["1", "10"], ["2", "20"], ["3", "30"]]
    assert "--until met" in result.output


def test_json_to_stdout_stays_parseable(pack):
    result = CliRunner().invoke(main, ["run", pack, "--ticks", "1", "--json", "-"])
    assert json.loads(result.stdout)["ticks"] == 1


def test_the_report_says_which_backend_ran(pack):
    # the default (auto) moves to the VM between two roots once the run has done SWITCH_AFTER of
    # work (here a tick is 3 commands and ROOT_WORK for its root); --backend forces one backend
    from emulator.runtime.auto import ROOT_WORK, SWITCH_AFTER

    def report(*args):
        return json.loads(invoke(pack, "--json", "-", *args).stdout)

    assert report("--ticks", "3")["backend"] == "python"
    assert report("--ticks", "3", "--backend", "numba")["backend"] == "numba"
    assert report("--ticks", "3", "--backend", "python")["backend"] == "python"
    ticks = str(SWITCH_AFTER // (3 + ROOT_WORK) + 50)
    switched, vm = report("--ticks", ticks), report("--ticks", ticks, "--backend", "numba")
    assert switched["backend"].startswith("python, then numba from tick ")
    assert (switched["scores"], switched["log"], switched["commands_per_tick"]) == (
        vm["scores"], vm["log"], vm["commands_per_tick"])


@pytest.mark.parametrize("backend", ["auto", "numba", "python"])
def test_sanitize_reports_overflow(pack, tmp_path, backend):
    out = tmp_path / "r.json"
    invoke(pack, "--ticks", "1", "--call", "t:big", "--sanitize", "--backend", backend,
           "--json", str(out))
    report = json.loads(out.read_text())
    assert report["scores"]["o"]["#m"] == -2147483648  # the stored value stays the game's
    [overflow] = report["overflows"]
    assert overflow["function"] == "t:big" and overflow["where"].endswith("big.mcfunction:2:1")
    assert (overflow["a"], overflow["b"], overflow["exact"]) == (2147483647, 1, 2147483648)


@pytest.mark.parametrize("args, message", [
    (["--set", "#n o"], "expected \"HOLDER OBJECTIVE VALUE\""),
    (["--set", "#n o 9999999999"], "outside the 32-bit range"),
    (["--until", "#n o x"], "expected an integer"),
    (["--mc", "banana"], "--mc"),
])
def test_bad_arguments_are_clean_errors(pack, args, message):
    result = invoke(pack, *args)
    assert result.exit_code == 2
    assert message in result.output
    assert "Traceback" not in result.output


def test_runtime_errors_are_reported_not_raised(pack, tmp_path):
    out = tmp_path / "r.json"
    result = invoke(pack, "--ticks", "1", "--call", "t:missing", "--json", str(out))
    assert result.exit_code == 1  # the run had an error (README: exit codes)
    assert invoke(pack, "--ticks", "1", "--call", "t:missing", "--no-fail-on-diagnostics").exit_code == 0
    report = json.loads(out.read_text())
    assert report["diagnostics"][0]["message"] == "Unknown function t:missing"
    assert report["scores"]["o"]["#n"] == 10


def test_call_with_macro_arguments(tmp_path):
    pack = str(write_pack(tmp_path / "pack", {**FUNCTIONS, "t:m": "$scoreboard players set #m o $(v)"}, TAGS))
    out = tmp_path / "r.json"
    invoke(pack, "--ticks", "1", "--call", "t:m {v: 12}", "--json", str(out))
    assert json.loads(out.read_text())["scores"]["o"]["#m"] == 12
    result = invoke(pack, "--call", "t:m {v: }")
    assert result.exit_code == 2 and "--call" in result.output


def test_log_prints_the_output_lines_by_tick(pack):
    # --log: what the run printed (here `say thirty` in the tick the sum reaches 30), with its tick
    # and the command's place; without --log the summary alone
    result = invoke(pack, "--ticks", "4", "--log")
    lines = [line for line in result.output.splitlines() if line.startswith("tick ")]
    assert len(lines) == 1 and lines[0].startswith("tick 2 say: [Server] thirty  (")
    assert not [line for line in invoke(pack, "--ticks", "4").output.splitlines() if line.startswith("tick ")]


def test_log_shows_a_tellraw_as_the_player_reads_it(tmp_path):
    # a tellraw's component as plain text (what PackTest's chat assertion reads too)
    pack = write_pack(tmp_path / "pack", {"t:go": 'tellraw @a [{"text":"a"},{"text":"b","color":"red"}]'}, {})
    lines = invoke(str(pack), "--player", "Steve@0,64,0", "--call", "t:go", "--log").output.splitlines()
    assert [line.split("  (")[0] for line in lines if line.startswith("tick ")] == ["tick 0 tellraw: ab"]
