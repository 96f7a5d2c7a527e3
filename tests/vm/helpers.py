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


def run_both(tmp_path: Path, body: str) -> Emulator:
    """``t:main`` (``body``) on both backends; the numba emulator, once both agree on the scores,
    every entity's NBT, the storage and the diagnostics."""
    from emulator.world.entities import entity_nbt
    from mcfunction_parser.nbt import to_snbt

    emus = {}
    for backend in ("numba", "python"):
        emu = emulator_for(tmp_path / backend, {"t:main": body}, backend=backend)
        emu.call("t:main")
        emus[backend] = emu
    numba, python = emus["numba"], emus["python"]
    assert numba.scores() == python.scores()
    assert [to_snbt(entity_nbt(e)) for e in numba.state.entities.entities] == \
        [to_snbt(entity_nbt(e)) for e in python.state.entities.entities]
    assert {k: to_snbt(v) for k, v in numba.state.storage.items()} == \
        {k: to_snbt(v) for k, v in python.state.storage.items()}
    assert [d.message for d in numba.diagnostics] == [d.message for d in python.diagnostics]
    return numba


def host_kinds(emu: Emulator) -> list[str]:
    """The AST node types of the host ops the VM handed to Python, in order."""
    return [type(run.node).__name__ for run in emu.backend.host_ops_run()]
