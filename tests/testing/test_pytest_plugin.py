"""The pytest plugin: fixtures, helpers, and mcfunction test files collected as items."""
import subprocess
import sys

import pytest

from emulator.testing.pytest_plugin import assert_entity_position, assert_position, assert_score

TESTS = {
    "demo/function/init.mcfunction": "scoreboard objectives add o dummy\nscoreboard players set $x o 4\n",
    "demo/test/good.mcfunction": "assert score $x o matches 4\n",
    "demo/test/bad.mcfunction": "say checking\nscoreboard players add $x o 1\nassert score $x o matches 4\n",
}


def test_dpemu_pack_loads_and_runs_load(pack, dpemu_pack):
    root = pack(TESTS, load=["demo:init"])
    emu = dpemu_pack(root, backend="python")
    assert emu.score("$x", "o") == 4
    assert dpemu_pack(root, load=False).score("$x", "o") is None


def test_emulator_fixture_is_empty(emulator):
    assert emulator.packs is None and emulator.backend_name in ("numba", "python")


def test_assert_score_tolerance_and_message(pack, dpemu_pack):
    emu = dpemu_pack(pack(TESTS, load=["demo:init"]))
    assert_score(emu, "$x", "o", 5, tolerance=1)
    with pytest.raises(AssertionError, match=r"^Expected score \$x o to be 6 ± 1, found 4$"):
        assert_score(emu, "$x", "o", 6, tolerance=1)
    with pytest.raises(AssertionError, match="found undefined"):
        assert_score(emu, "$nobody", "o", 0)


def test_assert_position():
    class Entity:
        pos = (1.0, 64.0, 2.0)

    assert_position(Entity(), (1.0, 64.0, 2.05), tolerance=0.1)
    with pytest.raises(AssertionError, match="off by 0.5"):
        assert_position((0.0, 0.0, 0.0), (0.3, 0.0, 0.4), tolerance=0.1)


def test_assert_entity_position(pack, dpemu_pack):
    root = pack({"demo/function/place.mcfunction": "summon marker 1 2 3 {Tags:[\"m\"]}\n"})
    emu = dpemu_pack(root)
    emu.call("demo:place")
    assert_entity_position(emu, "@e[tag=m]", (1.5, 2.0, 3.5))  # whole x and z are block centres
    assert_entity_position(emu, "@e[tag=m]", (1.5, 2.0, 3.55), tolerance=0.1)
    with pytest.raises(AssertionError, match="found 0"):
        assert_entity_position(emu, "@e[tag=none]", (0, 0, 0))
    with pytest.raises(AssertionError, match="off by 1"):
        assert_entity_position(emu, "@e[tag=m]", (1.5, 2.0, 4.5), tolerance=0.5)


def test_mcfunction_files_are_collected_only_when_asked(pack, tmp_path):
    root = pack(TESTS, load=["demo:init"])
    (tmp_path / "test_nothing.py").write_text("def test_py():\n    pass\n")
    base = [sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-o", "addopts="]
    command = base + ["--rootdir", str(tmp_path), str(tmp_path / "test_nothing.py")]
    plain = subprocess.run(command, capture_output=True, text=True, cwd=tmp_path)
    assert "1 passed" in plain.stdout
    run = subprocess.run(command + ["--mcfunction-tests", str(root), "--dpemu-backend", "python", "-rf"],
                         capture_output=True, text=True, cwd=tmp_path)
    assert run.returncode == 1, run.stdout + run.stderr
    assert "1 failed, 2 passed" in run.stdout
    assert "pack/data/demo/test/bad.mcfunction:3: Expected score $x o to match 4, found 5" in run.stdout
    assert "FAILED pack/data/demo/test/bad.mcfunction::demo:bad" in run.stdout
    # what the test printed, as pytest shows captured output
    assert "Captured chat call" in run.stdout and "say: [Server] checking" in run.stdout
    # the ini option names the packs instead (paths relative to the ini file)
    (tmp_path / "pytest.ini").write_text("[pytest]\nmcfunction_tests = pack/data/demo/test/good.mcfunction\n")
    ini = subprocess.run(base + ["-c", str(tmp_path / "pytest.ini"), str(tmp_path / "test_nothing.py")],
                         capture_output=True, text=True, cwd=tmp_path)
    assert "2 passed" in ini.stdout, ini.stdout + ini.stderr


def test_mcfunction_items_run_under_xdist(pack, tmp_path):
    """``pytest -n 2``: every worker collects the same items in the same order, so xdist spreads
    the mcfunction tests over the workers (and, through remote workers, over machines)."""
    pytest.importorskip("xdist")
    root = pack(TESTS, load=["demo:init"])
    (tmp_path / "test_nothing.py").write_text("def test_py():\n    pass\n")
    command = [sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-o", "addopts=", "-n", "2",
               "--rootdir", str(tmp_path), str(tmp_path / "test_nothing.py"), "--mcfunction-tests", str(root),
               "--dpemu-backend", "python", "-rf"]
    run = subprocess.run(command, capture_output=True, text=True, cwd=tmp_path)
    assert run.returncode == 1, run.stdout + run.stderr
    assert "created: 2/2 workers" in run.stdout
    assert "1 failed, 2 passed" in run.stdout, run.stdout
    assert "FAILED pack/data/demo/test/bad.mcfunction::demo:bad" in run.stdout


def test_mcfunction_items_read_the_game_jar_when_given(pack, tmp_path):
    """``--dpemu-game-jar`` (as ``dpemu test --game-jar``): the vanilla tags load under the packs."""
    import zipfile

    from tests.parser.pack.packbuild import tag

    jar = tmp_path / "client.jar"
    with zipfile.ZipFile(jar, "w") as archive:
        archive.writestr("data/minecraft/tags/block/logs.json", tag("minecraft:oak_log"))
    root = pack({"demo/test/log.mcfunction": "setblock ~ ~ ~ oak_log\nassert block ~ ~ ~ #minecraft:logs\n"})
    (tmp_path / "test_nothing.py").write_text("def test_py():\n    pass\n")
    command = [sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-o", "addopts=", "--rootdir", str(tmp_path),
               str(tmp_path / "test_nothing.py"), "--mcfunction-tests", str(root), "--dpemu-backend", "python", "-rA"]
    without = subprocess.run(command, capture_output=True, text=True, cwd=tmp_path)
    assert "1 passed, 1 skipped" in without.stdout, without.stdout  # inconclusive, never passed
    assert "inconclusive: " in without.stdout and "#minecraft:logs is not known without the game's data" in without.stdout
    judged = subprocess.run(command + ["--dpemu-allow-unmodelled"], capture_output=True, text=True, cwd=tmp_path)
    assert "1 failed, 1 passed" in judged.stdout, judged.stdout  # the tag matches nothing without the jar
    run = subprocess.run(command + ["--dpemu-game-jar", str(jar)], capture_output=True, text=True, cwd=tmp_path)
    assert run.returncode == 0 and "2 passed" in run.stdout, run.stdout + run.stderr
