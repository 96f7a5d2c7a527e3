"""Every subcommand takes pack folders and .zip files alike; a broken archive says so; output
paths are checked before the work starts."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from emulator.cli import main
from tests.backends.programs import write_pack
from tests.conftest import zip_folder

FUNCTIONS = {
    "t:load": "scoreboard objectives add o dummy",
    "t:main": "scoreboard players set #a o 5",
    "t:test/five": "function t:main\nassert score #a o matches 5",
    "t:bad": "scoreboard players sett #a o 5",
}
ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture
def zipped(tmp_path) -> Path:
    folder = write_pack(tmp_path / "pack", FUNCTIONS, {"minecraft:load": ["t:load"]})
    # the test file belongs in data/t/test/, not data/t/function/test/
    source = folder / "data/t/function/test/five.mcfunction"
    (folder / "data/t/test").mkdir(parents=True)
    source.rename(folder / "data/t/test/five.mcfunction")
    return zip_folder(folder, tmp_path / "pack.zip")


def invoke(*args):
    return CliRunner().invoke(main, [str(a) for a in args], catch_exceptions=False)


def test_run_takes_azip_folder(zipped):
    result = invoke("run", zipped, "--call", "t:main", "--watch", "#a o")
    assert result.exit_code in (0, 1) and "#a o = 5" in result.output


def test_profile_takes_azip_folder(zipped):
    result = invoke("profile", zipped, "--call", "t:main")
    assert "t:main" in result.output


def test_disasm_takes_azip_folder(zipped):
    result = invoke("disasm", zipped, "t:main")
    assert result.exit_code == 0 and "scoreboard players set #a o 5" in result.output


def test_test_takes_azip_folder(zipped):
    result = invoke("test", zipped)
    assert result.exit_code == 0 and result.output.strip().splitlines()[-1] == "1 passed, 0 failed"


def test_shot_takes_a_zipped_pool_pack(tmp_path):
    archive = zip_folder(ROOT / "datapack", tmp_path / "pool.zip")
    result = invoke("shot", archive, "--speed", "0.5")
    assert result.exit_code == 0 and "table at rest" in result.output


@pytest.mark.parametrize("command", [["run"], ["profile"], ["check"], ["test"], ["disasm"], ["shot"]])
def test_a_corrupt_archive_says_so(zipped, tmp_path, command):
    broken = tmp_path / "broken.zip"
    broken.write_bytes(zipped.read_bytes()[:200])
    args = [*command, broken] + (["t:main"] if command == ["disasm"] else [])
    result = invoke(*args)
    assert result.exit_code == 2 and "corrupt .zip archive" in result.output


def test_disasm_says_why_a_function_failed_to_load(zipped):
    result = invoke("disasm", zipped, "t:bad")
    assert result.exit_code == 2
    assert "failed to load" in result.output and "got 'sett'" in result.output


def test_k_matching_no_test_is_a_usage_error(zipped):
    result = invoke("test", zipped, "-k", "nothing-like-this")
    assert result.exit_code == 2 and "matches none of the 1 tests" in result.output


def test_a_junit_file_in_a_missing_folder_is_refused_before_the_tests(zipped, tmp_path):
    result = invoke("test", zipped, "--junit", tmp_path / "no" / "junit.xml")
    assert result.exit_code == 2 and "does not exist" in result.output and "passed" not in result.output


def test_a_zipped_pack_runs_as_a_process_without_traceback(zipped):
    # the whole program as a user starts it: exit code, first line, no traceback
    done = subprocess.run([sys.executable, "-m", "emulator", "test", str(zipped)], capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0 and done.stdout.splitlines()[0] == "PASS t:five"
    assert "Traceback" not in done.stderr
