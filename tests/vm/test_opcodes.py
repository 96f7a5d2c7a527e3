"""The opcode table (emulator/vm/opcodes.py): the generated loop is up to date, each family owns its
range of numbers and is served by one dispatch branch, only charging opcodes are charged, and the
disassembler and the profiler print the same names."""
from __future__ import annotations

import ast
import inspect
import json
from pathlib import Path

import numpy as np
from click.testing import CliRunner

from emulator.cli import main
from emulator.vm import generate, loop, opcodes
from tests.backends.programs import write_pack
from tests.vm.helpers import SETUP, emulator_for


def test_the_loop_is_generated_from_the_table_and_the_template():
    assert Path(loop.__file__).read_text() == generate.render(), "run python -m emulator.vm.generate"


def test_each_family_owns_its_range():
    ranges = opcodes.families()
    for family, (first, last) in ranges.items():
        inside = {op.family for op in opcodes.TABLE if first <= op.code <= last}
        assert inside == {family}, f"{family}'s range {first}..{last} holds {inside - {family}}"
    spans = sorted(ranges.values())
    assert all(a[1] < b[0] for a, b in zip(spans, spans[1:])), "ranges overlap"
    assert [op.code for op in opcodes.TABLE] == list(range(len(opcodes.TABLE)))
    for family, (first, last) in ranges.items():
        if first != last:
            assert (getattr(loop, f"FIRST_{family.upper()}"), getattr(loop, f"LAST_{family.upper()}")) == (first, last)
    assert {op.cost for op in opcodes.TABLE} <= {*opcodes.CHARGED, opcodes.CHECK, opcodes.FREE}


def _dispatch_tests() -> tuple[list[ast.expr], list[ast.stmt]]:
    """The tests of the dispatch chain in ``loop.run``, and its ``else`` body."""
    [run] = ast.parse(inspect.getsource(loop.run.py_func)).body
    [body] = [s for s in run.body if isinstance(s, ast.While)]
    [chain] = [s for s in body.body if isinstance(s, ast.If)]
    tests = []
    while True:
        tests.append(chain.test)
        if not (len(chain.orelse) == 1 and isinstance(chain.orelse[0], ast.If)):
            return tests, chain.orelse
        chain = chain.orelse[0]


def test_each_opcode_is_served_by_its_family_branch_alone():
    tests, otherwise = _dispatch_tests()
    assert otherwise, "the chain ends in an else"
    served: dict[int, set[str]] = {}
    for op in opcodes.TABLE:
        hits = [i for i, test in enumerate(tests)
                if eval(compile(ast.Expression(test), "loop", "eval"), {**vars(loop), "op": op.code})]
        assert len(hits) <= 1, f"{op.name} matches {len(hits)} dispatch tests"
        served.setdefault(hits[0] if hits else -1, set()).add(op.family)
    assert all(len(families) == 1 for families in served.values()), served
    assert served[-1] == {"halt"}
    assert len(served) == len(opcodes.families())


# a pack that runs most instruction kinds: scores, conditions, entity stages, stores, calls,
# tags, `if function`, returns, macros, host commands and stages
PACK = {
    "t:main": SETUP + "scoreboard objectives add tr trigger\nsummon marker 0 0 0 {Tags:[\"m\"]}\n"
    "summon marker 1 0 0 {Tags:[\"m\"]}\nscoreboard players set #a o 3\nscoreboard players add #a o 1\n"
    "scoreboard players remove #a o 1\nscoreboard players operation #a o *= #a o\n"
    "scoreboard players operation @e[tag=m] o += #a o\nscoreboard players get #a o\n"
    "scoreboard players reset #z o\nscoreboard players reset #z\nscoreboard players enable @s tr\n"
    "execute if score #a o matches 1.. if score #a o = #a o if entity @e[tag=m] run function t:f\n"
    "execute as @e[tag=m] at @s store result entity @s Pos[1] double 0.5 run scoreboard players get #a o\n"
    "execute as @e[tag=m] store result score @s o run data get entity @s Pos[0]\n"
    "execute store result score #r o run function #t:both\ntag @e[tag=m] add n\ntp @e[tag=n] ~ ~1 ~\n"
    "execute if function t:ret run return run function t:f\n",
    "t:f": "function t:mac {v:2}\nexecute positioned 1 2 3 store result storage t:s v int 1 run say hi\n"
           "tellraw @a \"x\"\nreturn fail",
    "t:mac": "$scoreboard players set #m o $(v)",
    "t:ret": "execute as @e[tag=m] run return 1",
    "t:g": "return run scoreboard players get #a o",
}


def test_only_charging_opcodes_are_charged(tmp_path):
    emu = emulator_for(tmp_path, PACK, tags={"t:both": ["t:g", "t:ret"]})
    emu.call("t:main")
    backend = emu.backend
    charged = {opcodes.BY_CODE[backend.program.rows[pc][0]] for pc in np.flatnonzero(backend.counts)}
    assert {op.cost for op in charged} <= set(opcodes.CHARGED), sorted(op.name for op in charged)
    assert {"entry", "stage", "condition"} <= {op.cost for op in charged}


def test_profile_and_disasm_print_the_same_names(tmp_path):
    pack = write_pack(tmp_path / "pack", PACK, {"t:both": ["t:g", "t:ret"]})
    runner = CliRunner()
    result = runner.invoke(main, ["profile", str(pack), "--call", "t:main", "--format", "json"])
    assert result.exit_code == 0, result.output
    profiled = {entry["line"]: [i["op"] for i in entry["instructions"]]
                for entry in json.loads(result.output)["lines"] if entry["path"].endswith("main.mcfunction")}
    result = runner.invoke(main, ["disasm", str(pack), "t:main"])
    assert result.exit_code == 0, result.output
    shown: dict[int, list[str]] = {}
    for text in result.output.splitlines():
        if text.startswith("      |"):
            shown[line].append(text.split()[2])
        else:
            line = int(text.split("|")[0])
            shown[line] = []
    names = {op.name for op in opcodes.TABLE}
    assert any("OPER*=" in ops for ops in profiled.values())
    for line, ops in profiled.items():  # the charged instructions of each line, in code order
        assert set(ops) <= names
        assert ops == [name for name in shown[line] if name in ops], line
