"""The smaller dispatch loops (emulator.vm.variants): what they serve, that each is the one a
program of its families runs, and that a program with a macro line runs the whole loop."""
from __future__ import annotations

import inspect
import re
from pathlib import Path

import pytest

from emulator.vm import generate, loop, opcodes, variants
from tests.vm.helpers import emulator_for

SMALL_PACK = {
    "t:main": "scoreboard objectives add o dummy\n"
              "scoreboard players set #a o 7\n"
              "scoreboard players operation #b o = #a o\n"
              "scoreboard players operation #b o *= #a o\n"
              "function t:add\n"
              "say hello\n"
              "return run function t:add",
    "t:add": "scoreboard players add #b o 2\nreturn 9",
}

TINY_PACK = {
    "t:main": "scoreboard objectives add o dummy\nscoreboard players set #a o 7\nfunction t:add\nsay hello\n"
              "scoreboard players remove #a o 1\nreturn run function t:add",
    "t:add": "scoreboard players add #b o 2\nreturn 9",
}


def test_the_whole_family_set_renders_the_whole_loop():
    assert generate.render(frozenset(op.family for op in opcodes.TABLE)) == Path(loop.__file__).read_text()


def test_the_small_loop_has_no_selector_entity_or_fork_branch():
    # what makes the whole loop slow to compile (see the module's docs): none of it in the small one
    text = generate.run_source(variants.SMALL)
    for used in ("_select(", "_matches(", "eints[", "efloats[", "etags[", "fork_contexts(", "_entity_context("):
        assert used not in text, used
    assert "case " not in text and "status = ST_HOST" in text


@pytest.mark.parametrize("pack, expected, operations", [(SMALL_PACK, (9, 7, 53), True), (TINY_PACK, (9, 6, 4), False)],
                         ids=["small", "tiny"])
def test_a_program_runs_its_tiers_loop_as_the_reference_runs_it(tmp_path, pack, expected, operations):
    results = {}
    for backend in ("numba", "python"):
        emu = emulator_for(tmp_path / backend, pack, backend=backend)
        results[backend] = (emu.call("t:main"), emu.score("#a", "o"), emu.score("#b", "o"))
        if backend == "numba":
            assert emu.backend.loop is variants.loop_for(emu.backend.program) is not loop
            assert ("_operate(" in inspect.getsource(emu.backend.loop.run)) == operations
    assert results["numba"] == results["python"] == expected


def test_a_macro_instance_past_the_small_set_moves_to_the_whole_loop(tmp_path):
    pack = {**SMALL_PACK,
            "t:main": "scoreboard objectives add o dummy\nscoreboard players set #a o 0\nfunction t:m {v: 3}",
            "t:m": "$execute if score #a o matches 0 run scoreboard players set #c o $(v)"}
    emu = emulator_for(tmp_path, pack)
    emu.call("t:main")
    assert emu.backend.loop is loop
    assert emu.score("#c", "o") == 3


def test_the_tiny_loop_has_no_operation_branch_and_borrows_only_what_it_reads():
    text = generate.run_source(variants.TINY)
    assert "_operate(" not in text and "FIRST_OPERATION" not in text and "status = ST_HOST" in text
    borrowed = re.findall(r"(\w+) = m\.\1\n", text)
    assert "values" in borrowed and "eints" not in borrowed and "ovf" in borrowed
    assert len(borrowed) < len(loop.MACHINE_FIELDS) // 2


def test_code_only_a_family_reaches_is_left_out_of_the_loops_without_it():
    # the set/add/remove on the holders a SELHOLDERS found (`# @needs selholders`): tiny has none
    assert "_set_score(" not in generate.run_source(variants.TINY)
    assert "_set_score(" in generate.run_source(variants.TINY | {"selholders"})
    assert "@needs" not in generate.render() and "_set_score(" in generate.render()


def test_the_small_loops_hand_objective_commands_to_python(tmp_path):
    # variants.TO_HOST: a program a small loop serves runs `scoreboard objectives add|remove` on the
    # host, with the same results (a second add fails; a remove returns the objectives left)
    pack = {"t:main": "scoreboard objectives add o dummy\nscoreboard objectives add p dummy\n"
                      "scoreboard players set #a p 1",
            "t:again": "return run scoreboard objectives add o dummy",
            "t:remove": "return run scoreboard objectives remove p"}
    results = {}
    for backend in ("numba", "python"):
        emu = emulator_for(tmp_path / backend, pack, backend=backend)
        results[backend] = [emu.call(f) for f in ("t:main", "t:again", "t:remove", "t:remove")] + [emu.objectives()]
        if backend == "numba":
            assert emu.backend.loop is not loop and "objective" not in emu.backend.loop.__doc__
            assert not any(opcodes.BY_CODE[code].family == "objective" for code in emu.backend.program.opcodes)
    assert results["numba"] == results["python"]
    assert results["python"][2:] == [1, 0, ["o"]]
