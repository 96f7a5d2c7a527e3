"""A run of scoreboard commands on names (set/add/remove, operations, ``execute if|unless score
... matches ... run CMD``) runs in the VM's ``_names_run`` (emulator/vm/loop.py.in), which reads each
next instruction itself. It must leave exactly where the one-instruction dispatch would, with the
registers it would leave: a command that fails (division by zero, an unknown or read-only objective:
the command fails, the function goes on), the quota spent in the middle of the run
(ExecutionContext.runCommandQueue checks it before each entry), ``@s`` or another command next, a
result read after it (a store, ``return run``, a condition's function), and the sanitizer's buffer
filling up (the VM hands Python its reports and runs the same operation again). Both backends run
every case and must agree."""
from __future__ import annotations

import pytest

from tests.backends.programs import run_root, write_pack

SETUP = ("scoreboard objectives add o dummy\nscoreboard objectives add hp health\nscoreboard players set #a o 7\nscoreboard players set #b o 3\n"
         "scoreboard players set #z o 0\nsummon marker 0 0 0 {Tags:[\"m\"]}\n")
RUN = ("scoreboard players operation #a o += #b o\nscoreboard players operation #b o *= #a o\n"
       "scoreboard players operation #a o %= #b o\nscoreboard players operation #c o -= #a o\n"
       "scoreboard players operation #b o >< #c o\nscoreboard players operation #a o > #c o\n")
MIXED = ("scoreboard players set #c o -4\nscoreboard players add #a o 9\n"
         "execute if score #a o matches 10.. run scoreboard players remove #b o 2\n"
         "execute unless score #a o matches 10.. run scoreboard players operation #b o += #a o\n"
         "scoreboard players operation #c o *= #b o\nexecute if score #q o matches 0 run scoreboard players set #q o 1\n"
         "execute unless score #q o matches 0 run scoreboard players add #q o 1\n")
LEAF = "scoreboard players add #l o 1\nscoreboard players operation #l o *= #b o\n"
BODIES = [
    RUN,
    RUN + "scoreboard players operation #a o /= #z o\n" + RUN,  # fails in the middle of a run
    RUN + "scoreboard players operation #a nope += #b o\n" + RUN,
    RUN + "scoreboard players operation #a o += #b nope\n" + RUN,
    RUN + "execute as @e[tag=m] run scoreboard players operation @s o = #a o\n" + RUN,
    RUN + "scoreboard players add #a o 5\n" + RUN + "scoreboard players operation #d o < #a o\n",
    MIXED,
    MIXED + "scoreboard players remove #a hp 1\n" + MIXED,  # read-only: fails in the middle of a run
    MIXED + "execute if score #a nope matches 1 run scoreboard players add #b o 1\n" + MIXED,
    MIXED + "execute store result score #r o run scoreboard players add #a o 3\n" + MIXED,
    MIXED + "execute store success score #r o run scoreboard players operation #a o %= #z o\n" + MIXED,
    MIXED + "execute if score #a o matches -2147483648.. run function t:leaf\n" + MIXED,
    MIXED + "execute store result score #r o if function t:leaf run scoreboard players get #a o\n" + MIXED,
    MIXED + "return run scoreboard players operation #b o -= #a o\n",
]


def _agree(tmp_path, body: str, limit: int | None = None, sanitize: bool = False) -> None:
    pack = write_pack(tmp_path / "pack", {"t:main": SETUP + "function t:run", "t:run": body, "t:leaf": LEAF})
    reference = run_root("python", pack, "t:main", limit=limit, sanitize=sanitize)
    vm = run_root("numba", pack, "t:main", limit=limit, sanitize=sanitize)
    assert vm.scores == reference.scores
    assert (vm.result, vm.cost, vm.cut) == (reference.result, reference.cost, reference.cut)
    assert vm.line_costs == reference.line_costs
    assert [m for m, _ in vm.diagnostics] == [m for m, _ in reference.diagnostics]
    assert sorted(vm.overflows) == sorted(reference.overflows)


@pytest.mark.parametrize("body", BODIES)
def test_a_run_of_scoreboard_commands_does_what_each_does(tmp_path, body):
    _agree(tmp_path, body)


@pytest.mark.parametrize("limit", range(8, 25))
def test_the_quota_cuts_a_run_where_it_cuts_each_operation(tmp_path, limit):
    _agree(tmp_path, BODIES[1], limit=limit)


@pytest.mark.parametrize("limit", range(8, 30, 3))
def test_the_quota_cuts_a_run_of_conditions_where_it_cuts_each(tmp_path, limit):
    _agree(tmp_path, MIXED * 3, limit=limit)


def test_a_run_that_fills_the_sanitizers_buffer(tmp_path):
    # every multiplication wraps (2^30 * 3 wraps to -2^30, and back): more reports than the VM's
    # buffer holds (1,024) in one run
    body = ("scoreboard players set #a o 1073741824\nscoreboard players set #m o 3\n"
            + "scoreboard players operation #a o *= #m o\n" * 1500)
    _agree(tmp_path, body, sanitize=True)
