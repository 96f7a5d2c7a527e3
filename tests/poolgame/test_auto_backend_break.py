"""The pool break on the auto backend (emulator.runtime.auto): the reference backend until the
switch, the VM after it, between two roots anywhere in the shot, gives the VM's break exactly."""
import pytest

from emulator.runtime.auto import AutoBackend
from emulator.runtime.factory import make_backend
from poolgame.shot import BREAK, new_table, play


def _break(backend):
    emu = new_table(backend=backend, sanitize=True)
    result = play(emu, BREAK)
    return emu, result


@pytest.fixture(scope="module")
def vm_break():
    return _break("numba")


# 1: right after the load tick (the whole shot on the VM); 30,000 and 120,000: in the shot's first
# ticks, amid the collisions of the rack (the break runs about 2,000 commands a tick)
@pytest.mark.parametrize("switch_after", [1, 30_000, 120_000])
def test_a_break_switching_backends_mid_run_is_the_vms(vm_break, switch_after):
    vm_emu, vm_result = vm_break
    auto = AutoBackend(make_backend("python"), lambda: make_backend("numba"), switch_after)
    emu, result = _break(auto)
    assert auto.switched_at is not None and auto.ran.startswith("python, then numba")
    assert result.balls == vm_result.balls
    assert (result.ticks, result.commands_per_tick, result.at_rest) == (vm_result.ticks, vm_result.commands_per_tick,
                                                                          vm_result.at_rest)
    assert emu.scores() == vm_emu.scores()
    assert emu.entities() == vm_emu.entities()
    assert [e.to_json() for e in emu.log] == [e.to_json() for e in vm_emu.log]
    assert not result.overflows and not result.diagnostics
