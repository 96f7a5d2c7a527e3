"""Helpers for the VM tests: write a pack from mcfunction text and run it on the numba backend."""
from __future__ import annotations

from pathlib import Path

from emulator import Emulator
from tests.backends.programs import write_pack

SETUP = "scoreboard objectives add o dummy\n"


def emulator_for(tmp_path: Path, functions: dict[str, str], tags: dict[str, list[str]] | None = None,
                 sanitize: bool = False, backend: str = "numba", stacks: bool = False) -> Emulator:
    pack = write_pack(tmp_path / "pack", functions, tags)
    emu = Emulator(backend=backend, sanitize=sanitize, stacks=stacks)
    emu.load(pack)
    assert not emu.load_diagnostics, [d.format() for d in emu.load_diagnostics]
    return emu


def run_main(tmp_path: Path, body: str, extra: dict[str, str] | None = None, **kwargs):
    """Run ``t:main`` (the objective ``o`` created first) once; returns (emulator, result)."""
    emu = emulator_for(tmp_path, {"t:main": SETUP + body, **(extra or {})}, **kwargs)
    return emu, emu.call("t:main")
