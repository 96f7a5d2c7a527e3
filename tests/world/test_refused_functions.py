"""A function with a line the game cannot parse is refused whole, on both backends.

Source: decompiled 1.21 server/ServerFunctionLibrary.reload (a function whose CommandFunction.fromLines
throws is logged "Failed to load function" and left out of the function map; tags are then built
against that map, so a tag requiring it fails to load: TagLoader.build).
"""
from __future__ import annotations

import pytest

from tests.world.world_emulator import emulator

BROKEN = "scoreboard players set #ran o 1\nexecute as @e[tag=x run say\nscoreboard players set #ran2 o 1"


@pytest.mark.parametrize("backend", ["python", "numba"])
def test_calling_a_refused_function_fails_as_unknown(tmp_path, backend):
    emu = emulator(tmp_path, backend, {
        "t:broken": BROKEN,
        "t:main": "execute store success score #ok o run function t:broken\nscoreboard players set #after o 1",
    })
    assert "t:broken" in emu.packs.refused and "t:broken" not in emu.packs.functions
    emu.call("t:main")
    assert emu.score("#ran", "o") is None and emu.score("#ran2", "o") is None  # no line of it runs
    assert emu.score("#ok", "o") == 0  # FunctionArgument: "Unknown function", the command fails
    assert emu.score("#after", "o") == 1
    assert any("t:broken" in d.message for d in emu.diagnostics)


@pytest.mark.parametrize("backend", ["python", "numba"])
def test_a_tag_requiring_a_refused_function_fails_to_load(tmp_path, backend):
    emu = emulator(tmp_path, backend, {"t:broken": BROKEN, "t:good": "scoreboard players set #good o 1",
                                       "t:main": "function #t:both"},
                   tags={"t:both": ["t:good", "t:broken"]})
    assert "t:both" in emu.packs.failed_tags
    emu.call("t:main")
    assert emu.score("#good", "o") is None
