"""The whole program as a user runs it (a subprocess): one exit-code rule for every subcommand
(README: 0 clean, 1 the pack or the run had errors, 2 usage errors, 130 interrupted), the first
line of output saying what happened, and never a traceback."""
from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from tests.backends.programs import write_pack
from tests.conftest import zip_folder

ROOT = Path(__file__).resolve().parents[2]
LOAD = {"minecraft:load": ["t:load"]}
BASE = {"t:load": "scoreboard objectives add o dummy", "t:ok": "scoreboard players set #a o 1"}


def dpemu(*args, timeout=300) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "emulator", *map(str, args)], capture_output=True, text=True,
                          timeout=timeout, cwd=ROOT)


def first_line(text: str) -> str:
    return text.strip().splitlines()[0] if text.strip() else ""


def start_up_time(*args) -> float:
    """Seconds the same command takes to start and finish on a trivial input on this machine now:
    a Ctrl-C sent sooner would interrupt the start-up, not the work (a loaded machine starts slowly)."""
    start = time.perf_counter()
    dpemu(*args)
    return time.perf_counter() - start


def interrupted(args: list[str], wait: float) -> tuple[subprocess.Popen, str, str]:
    """Starts dpemu, sends it Ctrl-C after `wait` seconds and collects its output. The child gets
    SIGINT's default action back: a shell starts background jobs with SIGINT ignored, and Python
    then installs no KeyboardInterrupt handler, so the signal would never arrive. A child that
    outlives the timeout is killed, never left spinning."""
    process = subprocess.Popen([sys.executable, "-m", "emulator", *args], cwd=ROOT, text=True,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    try:
        time.sleep(wait)
        process.send_signal(signal.SIGINT)
        out, err = process.communicate(timeout=120)
    finally:
        if process.poll() is None:
            process.kill()
            process.communicate()
    return process, out, err


def no_traceback(done: subprocess.CompletedProcess) -> None:
    assert "Traceback" not in done.stderr + done.stdout


@pytest.fixture
def pack(tmp_path):
    def make(functions=None, tags=LOAD):
        return write_pack(tmp_path / "pack", {**BASE, **(functions or {})}, tags)
    return make


def test_a_clean_run_exits_0(pack):
    done = dpemu("run", pack(), "--call", "t:ok", "--backend", "python")
    assert done.returncode == 0 and first_line(done.stdout).startswith("ticks: 1")
    no_traceback(done)


@pytest.mark.parametrize("functions, call, first", [
    ({"t:div": "scoreboard players set #z o 0\nscoreboard players operation #a o /= #z o"}, "t:div",
     "div.mcfunction:2:1: error: Cannot divide by zero"),
    ({}, "t:nowhere", "error: Unknown function t:nowhere"),
    ({"t:bad": "scoreboard players sett #a o 1"}, "t:ok", "bad.mcfunction:1:20: error"),
])
def test_errors_of_the_pack_or_the_run_exit_1(pack, functions, call, first):
    done = dpemu("run", pack(functions), "--call", call, "--backend", "python")
    assert done.returncode == 1, done.stderr
    assert first in first_line(done.stderr)
    no_traceback(done)
    allowed = dpemu("run", pack(functions), "--call", call, "--backend", "python", "--no-fail-on-diagnostics")
    assert allowed.returncode == 0


def test_a_missing_pack_mcmeta_and_a_broken_tag_exit_1(pack):
    root = pack()
    (root / "data/minecraft/tags/function/load.json").write_text('{"values": ["t:load", "t:missing"]}')
    done = dpemu("run", root, "--backend", "python")
    assert done.returncode == 1 and "function tag #minecraft:load fails to load" in first_line(done.stderr)
    (root / "pack.mcmeta").unlink()
    done = dpemu("run", root, "--backend", "python")
    assert done.returncode == 1 and "pack.mcmeta" in first_line(done.stderr)
    no_traceback(done)


def test_a_wrapped_value_under_the_sanitizer_exits_1(pack):
    root = pack({"t:wrap": "scoreboard players set #m o 2147483647\nscoreboard players add #m o 1"})
    done = dpemu("run", root, "--call", "t:wrap", "--sanitize", "--backend", "python")
    assert done.returncode == 1 and "overflows: 1" in done.stdout
    assert dpemu("run", root, "--call", "t:wrap", "--backend", "python").returncode == 0


def test_profile_prints_the_runs_diagnostics_and_exits_1(pack):
    done = dpemu("profile", pack(), "--call", "t:nowhere", "--backend", "python")
    assert done.returncode == 1 and "Unknown function t:nowhere" in done.stderr
    no_traceback(done)


@pytest.mark.parametrize("command", [
    ["run", "{pack}", "--json", "{missing}/r.json"], ["run", "{pack}", "--csv", "{missing}/r.csv"],
    ["profile", "{pack}", "-o", "{missing}/p.txt"], ["test", "{pack}", "--junit", "{missing}/j.xml"],
    ["shot", "--break", "--json", "{missing}/s.json"],
])
def test_an_output_in_a_missing_folder_is_a_usage_error_before_any_work(pack, tmp_path, command):
    args = [a.format(pack=pack(), missing=tmp_path / "no" / "such") for a in command]
    done = dpemu(*args)
    assert done.returncode == 2 and "does not exist" in done.stderr
    assert done.stdout == ""  # nothing ran
    no_traceback(done)


@pytest.mark.parametrize("args, option", [
    (["--ticks", "99999999999999999999"], "--ticks"), (["--set", "@e o 1"], "--set"),
    (["--set", "#a nowhere 1"], "--set"), (["--ticks", "-1"], "--ticks"),
])
def test_bad_numbers_and_holders_are_usage_errors(pack, args, option):
    done = dpemu("run", pack(), "--backend", "python", *args)
    assert done.returncode == 2 and option in done.stderr
    no_traceback(done)


def test_csv_dash_is_standard_output_and_no_progress_label_leaks_into_logs(pack):
    done = dpemu("run", pack(), "--backend", "python", "--ticks", "300", "--watch", "#a o", "--call", "t:ok",
                 "--csv", "-")
    assert done.returncode == 0
    assert "tick,#a o" in done.stdout and "300,1" in done.stdout
    assert all(line.strip() != "ticks" and "%" not in line for line in done.stderr.splitlines())  # no bar
    assert not (ROOT / "-").exists()


def test_a_self_calling_function_prints_a_folded_traceback(pack):
    done = dpemu("run", pack({"t:loop": "function t:loop"}), "--call", "t:loop", "--backend", "python", "--json", "-")
    assert done.returncode == 0  # the quota cut is the game's warning, not an error
    assert len(done.stderr.splitlines()) < 20 and "more frames of t:loop" in done.stderr
    report = json.loads(done.stdout)
    assert len(done.stdout) < 50_000
    assert {"folded": 65534, "functions": ["t:loop"]} in report["diagnostics"][0]["traceback"]


def test_a_version_the_pack_does_not_support_is_said(tmp_path):
    done = dpemu("run", ROOT / "datapack", "--mc", "1.20.4", "--backend", "python")
    assert "pack supports formats 48-94, not 1.20.4" in done.stderr


def test_ctrl_c_prints_what_ran_and_exits_130(pack):
    root = pack({"t:tick": "scoreboard players add #n o 1"}, {**LOAD, "minecraft:tick": ["t:tick"]})
    args = ["run", str(root), "--backend", "python", "--watch", "#n o", "--ticks"]
    wait = 2 * start_up_time(*args, "1") + 2
    process, out, err = interrupted([*args, "100000000"], wait)
    assert process.returncode == 130, err
    assert "interrupted" in err and first_line(out).startswith("ticks: ")
    assert "Traceback" not in err and "Aborted" not in err
    ticks = int(first_line(out).split()[1])
    watched = int(out.split("#n o = ")[1].split()[0])
    assert 0 < ticks < 100000000 and watched in (ticks, ticks + 1)  # the tick Ctrl-C cut may be half done


@pytest.mark.parametrize("args, status, first", [
    (["shot", "--speed", "nan"], 2, "Usage: dpemu shot"),
    (["shot", "--speed", "1", "--tip", "0.1,inf"], 2, "Usage: dpemu shot"),
    (["shot", "--break", "--max-ticks", "20"], 1, "ball"),
    (["shot", "--speed", "7"], 1, "Pool: shot refused: --speed must be 0.001..6.5 m/s"),
])
def test_shot_as_a_process(args, status, first):
    done = dpemu(*args)
    assert done.returncode == status, done.stderr
    assert first_line(done.stdout or done.stderr).startswith(first)
    if "--max-ticks" in args:
        assert "still moving" in done.stdout
    no_traceback(done)


def test_zipped_and_broken_packs_as_a_process(pack, tmp_path):
    archive = zip_folder(pack({"t:bad": "scoreboard players sett #a o 1"}), tmp_path / "p.zip")
    run = dpemu("run", archive, "--call", "t:ok", "--watch", "#a o", "--backend", "python")
    assert run.returncode == 1 and "#a o = 1" in run.stdout  # the broken function is a load error
    assert "bad.mcfunction:1:20: error" in first_line(run.stderr)
    disasm = dpemu("disasm", archive, "t:bad")
    assert disasm.returncode == 2 and "failed to load" in disasm.stderr
    broken = tmp_path / "broken.zip"
    broken.write_bytes(archive.read_bytes()[:100])
    for command in ("run", "check", "test", "profile"):
        done = dpemu(command, broken)
        assert done.returncode == 2 and "is a corrupt .zip archive" in done.stderr, command
        no_traceback(done)


def test_a_huge_literal_is_a_parse_error_at_its_column_as_a_process(pack):
    root = pack({"t:big": "scoreboard players set #a o " + "9" * 1_000_000})
    done = dpemu("check", root)
    assert done.returncode == 1
    assert "big.mcfunction:1:29: error: integer 99999999999999999999... (1000000 characters) is out of range" \
        in first_line(done.stdout)
    no_traceback(done)


def test_ctrl_c_during_a_check_exits_130_without_a_traceback(tmp_path):
    # a pack big enough to be still parsing when the signal arrives
    functions = {f"t:f{i}": "\n".join(f"scoreboard players set #a{j} o {j}" for j in range(400)) for i in range(3000)}
    root = write_pack(tmp_path / "big", functions, {})
    wait = 1.5 * start_up_time("check", write_pack(tmp_path / "small", {"t:f": "say hi"}, {})) + 1
    process, out, err = interrupted(["check", str(root)], wait)
    if process.returncode == 0:  # the check finished before the signal: nothing to judge
        pytest.skip("the check ended before Ctrl-C")
    assert process.returncode == 130 and "interrupted" in err
    assert "Traceback" not in err and "Aborted" not in err
