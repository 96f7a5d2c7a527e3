"""``dpemu``: the subcommands --help lists, and what neither --help nor a python-backend run imports."""
from __future__ import annotations

import subprocess
import sys

import pytest

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


@pytest.mark.parametrize("command", ["run", "profile"])
def test_the_python_backend_imports_no_numba(tmp_path, command):
    pack = write_pack(tmp_path / "pack", {"t:tick": "scoreboard objectives add o dummy\nsay hi"},
                      {"minecraft:tick": ["t:tick"]})
    assert "numba modules: []" in dpemu(command, str(pack), "--backend", "python", "--ticks", "2")
