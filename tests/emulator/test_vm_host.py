"""Host ops inside VM chains: context modifiers, conditions and stores the VM hands to Python."""
from __future__ import annotations

import pytest

from mcfunction_parser.nbt import Int
from vm_helpers import run_main

pytestmark = pytest.mark.parametrize("backend", ["numba", "python"])  # the reference must agree

HELPERS = {"t:five": "return 5", "t:plain": "scoreboard players add #plain o 1"}


def test_modifiers_keep_the_server_context_and_run_functions(tmp_path, backend):
    emu, result = run_main(tmp_path, "execute positioned 1 2 3 align xz rotated 90 0 in minecraft:the_nether "
                                     "run function t:plain\n"
                                     "execute store result score #r o positioned ~ ~1 ~ run function t:five\n"
                                     "execute anchored eyes if function t:five run scoreboard players set #if o 1\n"
                                     "execute in minecraft:the_end run return run function t:five",
                           HELPERS, backend=backend)
    assert emu.score("#plain", "o") == 1
    assert emu.score("#r", "o") == 5
    assert emu.score("#if", "o") == 1
    assert result == 5
    assert emu.diagnostics == []


def test_entity_stages_select_nothing(tmp_path, backend):
    emu, _ = run_main(tmp_path, "execute as @e run function t:plain\n"
                                "execute store success score #s o as @a run scoreboard players set #x o 1\n"
                                "execute unless entity @e run scoreboard players set #none o 1\n"
                                "execute store result score #count o if entity @e", HELPERS, backend=backend)
    assert emu.score("#plain", "o") is None and emu.score("#x", "o") is None
    assert emu.score("#s", "o") is None  # no context ran the command: nothing stored
    assert emu.score("#none", "o") == 1
    assert emu.score("#count", "o") == 0  # the final condition failed: store result 0


def test_store_into_storage(tmp_path, backend):
    emu, _ = run_main(tmp_path, "scoreboard players set #a o 7\n"
                                "execute store result storage t:s v int 2 run scoreboard players get #a o",
                      backend=backend)
    assert emu.state.storage["t:s"]["v"] == Int(14)


def test_host_stage_costs(tmp_path, backend):
    emu, _ = run_main(tmp_path, "", {"t:f": "execute positioned 0 0 0 as @e run say hi"}, backend=backend)
    result = emu.runtime.call("t:f")
    assert result.cost == 1 + 2  # two stages, no context left to run `say`


def test_sanitizer_sees_host_arithmetic(tmp_path, backend):
    emu, _ = run_main(tmp_path, "scoreboard players set #a o 2147483647\nscoreboard players set #b o 5\n"
                                "scoreboard players add * o 1", sanitize=True, backend=backend)
    assert emu.score("#a", "o") == -2147483648
    assert [(o.function, o.loc.line, o.op, o.a, o.b, o.exact) for o in emu.overflows] == [
        ("t:main", 4, "add", 2147483647, 1, 2147483648)]
