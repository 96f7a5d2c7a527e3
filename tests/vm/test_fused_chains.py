"""`execute if|unless score H O matches R run CMD`, CMD one instruction (a score command on names or
``@s``, a plain function call), compiles to IFRUN then CMD (``Compiler.score_test_run``): the
chain's entry check and its condition stage in one instruction, and no ENDCMD. It must do all the
whole chain does: ExecuteCommand's condition stage (a missing score fails ``if`` and passes
``unless``; ``@s`` without an executor drops the context either way; an unknown objective is an
error), BuildContexts' fork limit, and ExecutionContext.runCommandQueue's quota check before the
chain and again before CMD, each charged once. Both backends run every case and must agree."""
from __future__ import annotations

import pytest

from emulator.vm import loop as vm
from tests.backends.programs import run_root, write_pack
from tests.vm.helpers import SETUP, emulator_for

PRELUDE = SETUP + "scoreboard players set #one o 1\nscoreboard players set #zero o 0\n"
LINES = [
    "execute if score #one o matches 1 run scoreboard players set #x o 1",
    "execute if score #one o matches 2.. run scoreboard players set #x o 1",
    "execute unless score #one o matches 2.. run scoreboard players add #x o 5",
    "execute if score #none o matches ..0 run scoreboard players set #x o 1",  # no score: `if` fails
    "execute unless score #none o matches 0 run scoreboard players remove #x o 3",  # and `unless` passes
    "execute if score @s o matches 1 run scoreboard players set #x o 1",  # the server has no score of its own
    "execute unless score @s o matches 1 run scoreboard players set #x o 1",
    "execute if score #one nope matches 1 run scoreboard players set #x o 1",  # unknown objective: an error
    "execute if score #one o matches 1 run scoreboard players operation #x o /= #zero o",  # CMD fails
    "execute if score #one o matches 1 run scoreboard players set #x nope 1",
    "execute if score #one o matches 1 run function t:ret",
    "execute if score #one o matches 1 run function t:add\nexecute if score #x o matches 4 run function t:add",
    "execute as @e[tag=m] if score @s o matches 1.. run scoreboard players add @s o 1\n"
    "execute as @e[tag=m] run function t:self",
]
FUNCTIONS = {
    "t:ret": "scoreboard players set #r o 2\nreturn 9",
    "t:add": "scoreboard players add #x o 2",
    "t:self": "execute if score @s o matches 2 run scoreboard players operation @s o *= #one o\n"
              "execute unless score @s o matches 2 run scoreboard players set @s o 7",
    "t:marks": 'summon marker 0 0 0 {Tags:["m"]}\nsummon marker 1 0 0 {Tags:["m"]}\n'
               "scoreboard players set @e[tag=m,limit=1] o 1",
}


def _agree(tmp_path, body: str, limit: int | None = None, prelude: str = PRELUDE) -> None:
    functions = {**FUNCTIONS, "t:main": prelude + "function t:marks\n" + body + "\nscoreboard players set #end o 1"}
    pack = write_pack(tmp_path / "pack", functions)
    reference = run_root("python", pack, "t:main", limit=limit)
    fused = run_root("numba", pack, "t:main", limit=limit)
    assert fused.scores == reference.scores
    assert (fused.result, fused.cost, fused.cut) == (reference.result, reference.cost, reference.cut)
    assert fused.line_costs == reference.line_costs
    assert [m for m, _ in fused.diagnostics] == [m for m, _ in reference.diagnostics]


@pytest.mark.parametrize("line", LINES)
def test_a_fused_chain_does_what_the_chain_does(tmp_path, line):
    _agree(tmp_path, line)


@pytest.mark.parametrize("limit", range(1, 16))
def test_the_quota_cuts_a_fused_chain_where_it_cuts_the_chain(tmp_path, limit):
    # the quota is checked before the chain (its stage is charged) and again before CMD
    _agree(tmp_path, "\n".join(LINES[:3] + LINES[10:12]), limit=limit)


def test_the_fork_limit_fails_a_passing_fused_chain(tmp_path):
    # BuildContexts: the one context the condition passes on reaches maxCommandForkCount 1
    _agree(tmp_path, "gamerule maxCommandForkCount 1\n" + "\n".join(LINES[:3]))


def test_the_simple_forms_are_fused_and_the_others_are_not(tmp_path):
    emu = emulator_for(tmp_path, {"t:a": "execute if score #a o matches 1 run scoreboard players set #b o 1",
                                  "t:b": "execute if score #a o matches 1 run say x",
                                  "t:c": "execute if score #a o matches 1 if score #b o matches 1 run function t:a",
                                  "t:d": "execute if score @e[limit=1] o matches 1 run function t:a",
                                  "t:e": "execute if score #a o matches 1 run scoreboard players set @e o 1"})
    program = emu.backend.program
    ops = {fn: [row[0] for pc, row in enumerate(program.rows) if program.function_of(pc) == fn]
           for fn in ("t:a", "t:b", "t:c", "t:d", "t:e")}
    assert ops["t:a"] == [vm.OP_IFRUN, vm.OP_SET, vm.OP_FEND]
    assert all(vm.OP_IFRUN not in ops[fn] and vm.OP_CMD in ops[fn] for fn in ("t:b", "t:c", "t:d", "t:e"))
