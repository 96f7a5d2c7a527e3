"""The pool break runs its tick path (pool:tick and what it calls, and pool:api/shot) inside the
VM: no host op runs, and the outcome is the reference backend's."""
from __future__ import annotations

from poolgame.shot import BREAK, new_table, play

def test_break_runs_without_host_ops():
    emu = new_table()
    emu.backend.host_runs.clear()  # the table's setup (summon, kill, objectives add) is not the tick path
    result = play(emu, BREAK)
    assert result.at_rest
    assert any(ball.pocketed for ball in result.balls)  # the pocket path ran too
    ran = [(run.function, type(run.node).__name__, run.runs) for run in emu.backend.host_ops_run()]
    assert ran == []


def test_break_agrees_with_the_reference_backend():
    vm, reference = new_table(), new_table(backend="python")
    vm_result, reference_result = play(vm, BREAK), play(reference, BREAK)
    assert vm_result.balls == reference_result.balls
    assert vm_result.commands_per_tick == reference_result.commands_per_tick
    assert vm.entities("@e[tag=pool.ball]") == reference.entities("@e[tag=pool.ball]")
