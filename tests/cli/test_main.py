"""``dpemu``: the subcommands --help lists, and what neither --help nor a python-backend run imports
(start-up time: bench/run.py measures it)."""
from __future__ import annotations

import importlib
import os
import subprocess
import sys

import pytest

from emulator.cli import _BUILTIN
from tests.backends.programs import write_pack

# runs dpemu with the arguments after it, then prints the numba modules loaded
SCRIPT = ("import sys\nfrom emulator.cli import main\ntry:\n    main(sys.argv[1:])\nexcept SystemExit:\n    pass\n"
          "print('numba modules:', sorted(m for m in sys.modules if m.split('.')[0] == 'numba'))")


def dpemu(*args: str) -> str:
    return subprocess.run([sys.executable, "-c", SCRIPT, *args], capture_output=True, text=True, check=True).stdout


def test_help_lists_every_subcommand_without_importing_numba():
    out = dpemu("--help")
    assert all(name in out for name in ("check", "disasm", "profile", "run", "shot", "test"))
    assert "numba modules: []" in out


def test_help_loads_neither_the_emulator_nor_the_parser():
    script = ("import sys\nfrom emulator.cli import main\ntry:\n    main(['--help'])\nexcept SystemExit:\n    pass\n"
              "print(sorted(m for m in sys.modules if m.split('.')[0] in ('mcfunction_parser', 'numpy')"
              " or m in ('emulator.api', 'poolgame.shot')))")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True)
    assert done.stdout.strip().splitlines()[-1] == "[]"


@pytest.mark.parametrize("name", sorted(_BUILTIN))
def test_the_listed_help_is_the_commands_own_first_line(name):
    target, line = _BUILTIN[name]
    module, attribute = target.split(":")
    command = getattr(importlib.import_module(module), attribute)
    assert " ".join(command.help.split("\n\n")[0].split()) == line


@pytest.mark.parametrize("command", ["run", "profile"])
def test_the_python_backend_imports_no_numba(tmp_path, command):
    pack = write_pack(tmp_path / "pack", {"t:tick": "scoreboard objectives add o dummy\nsay hi"},
                      {"minecraft:tick": ["t:tick"]})
    assert "numba modules: []" in dpemu(command, str(pack), "--backend", "python", "--ticks", "2")


def test_a_short_run_on_the_default_backend_imports_no_numba(tmp_path):
    # auto (emulator.runtime.auto): the reference backend until the run has done SWITCH_AFTER of work
    pack = write_pack(tmp_path / "pack", {"t:tick": "scoreboard objectives add o dummy\nsay hi"},
                      {"minecraft:tick": ["t:tick"]})
    out = dpemu("run", str(pack), "--ticks", "2")
    assert "backend: python\n" in out and "numba modules: []" in out


@pytest.mark.skipif(not os.path.isdir("/proc/self/task"), reason="counts the threads in /proc")
def test_a_run_starts_no_blas_threads(tmp_path):
    # numpy's OpenBLAS pool spins each idle thread for about 0.1 s of CPU after it starts
    pack = write_pack(tmp_path / "pack", {"t:a": "scoreboard objectives add o dummy"})
    script = SCRIPT.replace("print('numba modules:', sorted(m for m in sys.modules if m.split('.')[0] == 'numba'))",
                            "import os, numpy\nprint('threads:', len(os.listdir('/proc/self/task')))")
    env = {k: v for k, v in os.environ.items() if k != "OPENBLAS_NUM_THREADS"}
    args = [sys.executable, "-c", script, "run", str(pack), "--call", "t:a", "--backend", "python"]
    assert "threads: 1" in subprocess.run(args, capture_output=True, text=True, check=True, env=env).stdout
    chosen = subprocess.run(args, capture_output=True, text=True, check=True, env={**env, "OPENBLAS_NUM_THREADS": "2"})
    assert "threads: 2" in chosen.stdout  # the user's choice stands


def test_a_built_in_subcommand_reads_no_package_metadata(tmp_path):
    # the installed packages' entry points (importlib.metadata reading every package) are looked up
    # only to list the subcommands or to find one another package adds
    pack = write_pack(tmp_path / "pack", {"t:a": "scoreboard objectives add o dummy"})
    script = SCRIPT.replace("m.split('.')[0] == 'numba'", "m == 'importlib.metadata'")
    script = script.replace("numba modules", "metadata")
    done = subprocess.run([sys.executable, "-c", script, "run", str(pack), "--call", "t:a", "--backend", "python"],
                          capture_output=True, text=True, check=True)
    assert "metadata: []" in done.stdout
