"""The distribution as a user gets it: the wheel ``python -m build`` makes, installed into a fresh
venv outside the clone, runs the main job (the pool datapack ships inside it) and checks a
zipped pack."""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def _run(args, cwd, timeout=600) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV")}
    return subprocess.run(args, cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout)


@pytest.fixture(scope="module")
def wheel(tmp_path_factory) -> Path:
    work = tmp_path_factory.mktemp("dist")
    source = work / "source"  # a copy of the tracked files: building leaves build/ and egg-info behind
    for name in subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True, check=True).stdout.split():
        if (ROOT / name).is_file():
            (source / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(ROOT / name, source / name)
    built = _run([sys.executable, "-m", "build", "--wheel", "--outdir", str(work), str(source)], cwd=work)
    assert built.returncode == 0, built.stdout[-2000:] + built.stderr[-2000:]
    return next(work.glob("dpemu-*.whl"))


@pytest.fixture(scope="module")
def installed(wheel) -> Path:
    """The bin folder of a fresh venv with the built wheel installed."""
    work = wheel.parent
    venv = work / "venv"
    assert _run([sys.executable, "-m", "venv", str(venv)], cwd=work).returncode == 0
    pip = _run([str(venv / "bin" / "pip"), "install", "-q", str(wheel)], cwd=work)
    assert pip.returncode == 0, pip.stderr[-2000:]
    return venv / "bin"


def test_the_wheel_carries_the_pool_datapack(wheel):
    names = set(zipfile.ZipFile(wheel).namelist())
    source = {"poolgame/datapack/" + p.relative_to(ROOT / "datapack").as_posix()
              for p in (ROOT / "datapack").rglob("*") if p.is_file()}
    assert source and source <= names, sorted(source - names)[:5]


def test_the_installed_dpemu_plays_a_break_outside_the_clone(installed, tmp_path):
    result = _run([str(installed / "dpemu"), "shot", "--break"], cwd=tmp_path)
    assert result.returncode == 0, result.stdout[-2000:] + result.stderr[-2000:]
    assert "table at rest" in result.stdout
    assert "Traceback" not in result.stderr


def test_the_installed_dpemu_checks_a_zipped_pack(installed, tmp_path):
    archive = tmp_path / "pack.zip"
    with zipfile.ZipFile(archive, "w") as z:
        z.writestr("pack.mcmeta", '{"pack": {"pack_format": 48, "description": "z"}}')
        z.writestr("data/z/function/main.mcfunction", "scoreboard objectives add o dummy\n")
        z.writestr("data/minecraft/tags/function/load.json", '{"values": ["z:main"]}')
    result = _run([str(installed / "dpemu"), "check", str(archive)], cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    assert result.stdout.strip().splitlines()[-1].startswith("3 files, 1 function, 1 command: 0 errors")
