"""A run of `scoreboard players operation` lines on names loops inside the VM's operation branch
(emulator/vm/loop.py.in), each reading the next instruction itself. It must leave that loop exactly
where the one-instruction dispatch would: an operation that fails (division by zero, an unknown
objective: the command fails, the function goes on), the quota spent in the middle of the run
(ExecutionContext.runCommandQueue checks it before each entry), an operation on ``@s`` or another
command next, and the sanitizer's buffer filling up (the VM hands Python its reports and runs the
same operation again). Both backends run every case and must agree."""
from __future__ import annotations

import pytest

from tests.backends.programs import run_root, write_pack

SETUP = ("scoreboard objectives add o dummy\nscoreboard players set #a o 7\nscoreboard players set #b o 3\n"
         "scoreboard players set #z o 0\nsummon marker 0 0 0 {Tags:[\"m\"]}\n")
RUN = ("scoreboard players operation #a o += #b o\nscoreboard players operation #b o *= #a o\n"
       "scoreboard players operation #a o %= #b o\nscoreboard players operation #c o -= #a o\n"
       "scoreboard players operation #b o >< #c o\nscoreboard players operation #a o > #c o\n")
BODIES = [
    RUN,
    RUN + "scoreboard players operation #a o /= #z o\n" + RUN,  # fails in the middle of a run
    RUN + "scoreboard players operation #a nope += #b o\n" + RUN,
    RUN + "scoreboard players operation #a o += #b nope\n" + RUN,
    RUN + "execute as @e[tag=m] run scoreboard players operation @s o = #a o\n" + RUN,
    RUN + "scoreboard players add #a o 5\n" + RUN + "scoreboard players operation #d o < #a o\n",
]


def _agree(tmp_path, body: str, limit: int | None = None, sanitize: bool = False) -> None:
    pack = write_pack(tmp_path / "pack", {"t:main": SETUP + "function t:run", "t:run": body})
    reference = run_root("python", pack, "t:main", limit=limit, sanitize=sanitize)
    vm = run_root("numba", pack, "t:main", limit=limit, sanitize=sanitize)
    assert vm.scores == reference.scores
    assert (vm.result, vm.cost, vm.cut) == (reference.result, reference.cost, reference.cut)
    assert vm.line_costs == reference.line_costs
    assert [m for m, _ in vm.diagnostics] == [m for m, _ in reference.diagnostics]
    assert sorted(vm.overflows) == sorted(reference.overflows)


@pytest.mark.parametrize("body", BODIES)
def test_a_run_of_operations_does_what_each_does(tmp_path, body):
    _agree(tmp_path, body)


@pytest.mark.parametrize("limit", range(7, 24))
def test_the_quota_cuts_a_run_where_it_cuts_each_operation(tmp_path, limit):
    _agree(tmp_path, BODIES[1], limit=limit)


def test_a_run_that_fills_the_sanitizers_buffer(tmp_path):
    # every multiplication wraps (2^30 * 3 wraps to -2^30, and back): more reports than the VM's
    # buffer holds (1,024) in one run
    body = ("scoreboard players set #a o 1073741824\nscoreboard players set #m o 3\n"
            + "scoreboard players operation #a o *= #m o\n" * 1500)
    _agree(tmp_path, body, sanitize=True)
