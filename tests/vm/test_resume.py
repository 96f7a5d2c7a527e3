"""How the backend resumes the VM: ``run`` takes the machine by the address of its descriptor and
its type (nothing is unboxed on a resume), through its compiled entry point; a plain function
standing in for ``run`` (bench/run.py's timer of the VM's share of a tick) gets the same arguments
and calls the dispatcher with them."""
from __future__ import annotations

import numpy as np
from numba import njit

from emulator.vm import backend, loop as vm
from tests.vm.helpers import SETUP, emulator_for, run_both

FUNCTIONS = {"t:setup": SETUP, "t:f": "scoreboard players add #n o 1\ntime query gametime\n" * 3}


def test_host_ops_resume_the_machine_by_its_address(tmp_path):
    emu = emulator_for(tmp_path, FUNCTIONS)
    emu.call("t:setup")
    emu.call("t:f")
    backend = emu.backend
    first = backend.address
    emu.call("t:f")
    assert backend.address == first  # the same arrays: the same machine
    assert emu.score("#n", "o") == 6


def test_entities_coming_and_going_keep_the_machine(tmp_path):
    """The VM reads how many entities live from the table's ``live``: a summon or a kill changes no
    array the machine holds (only a table grown past its rows makes it again), and the selectors
    find the entities as they are."""
    count = "execute store result score #n o if entity @e[type=marker]\n"
    emu = emulator_for(tmp_path, {"t:setup": SETUP, "t:grow": "summon marker\n" + count,
                                  "t:shrink": "kill @e[type=marker,limit=1]\n" + count})
    emu.call("t:setup")
    emu.call("t:grow")
    backend = emu.backend
    first, rows = backend.machine, emu.state.entities.table.ints.shape[0]
    for n in range(2, 5):
        emu.call("t:grow")
        assert emu.score("#n", "o") == n
    emu.call("t:shrink")
    assert emu.score("#n", "o") == 3
    assert emu.state.entities.table.ints.shape[0] == rows and backend.machine is first


def test_a_plain_function_standing_in_for_run_is_called_with_the_same_arguments(tmp_path):
    emu = emulator_for(tmp_path, FUNCTIONS)
    emu.call("t:setup")
    emu.call("t:f")
    loop, calls = emu.backend.loop, []
    run = loop.run

    def timed(*args):
        calls.append(args)
        return run(*args)

    loop.run = timed
    try:
        emu.backend.stale = True  # the backend takes the run it finds when it makes its machine
        emu.call("t:f")
    finally:
        loop.run = run
        emu.backend.stale = True
    assert len(calls) == 4  # the root's start and a resume after each of the three host commands
    assert emu.score("#n", "o") == 6


@njit
def _read(address, machine_type):
    m = vm._machine_at(address, machine_type)
    m.regs[0] = m.values[1, 2] + m.code[2, 1] + m.floats[4]
    return m.values.shape[0] * 100 + m.values.shape[1] * 10 + m.values.strides[0] // 8


def test_run_makes_the_machines_arrays_from_its_descriptor():
    arrays = [np.zeros(2, dtype=np.int64) for _ in vm.MACHINE_FIELDS]
    fields = dict(zip(vm.MACHINE_FIELDS, arrays))
    wide = np.arange(40, dtype=np.int32).reshape(5, 8)
    fields.update(code=wide, values=wide[::2, 1:4], floats=np.arange(6, dtype=np.float64) / 2)  # values: strided
    machine = vm.Machine(**fields)
    descriptor, machine_type = vm.machine(machine)
    assert descriptor[0] == wide.ctypes.data and list(descriptor[1:5]) == [5, 8, 32, 4]  # code: data, shape, strides
    assert _read(descriptor.ctypes.data, machine_type) == 3 * 100 + 3 * 10 + 8
    assert fields["regs"][0] == wide[2, 3] + wide[2, 1] + 2  # values[1, 2] is wide[2, 3]


def test_contexts_beyond_the_first_rows_grow_the_arrays_and_agree_with_the_reference(tmp_path):
    markers = 40  # 40 x 40 contexts: past the first rows of the context arrays and of the fork stack
    body = (SETUP + 'summon marker 0 0 0 {Tags:["x"]}\n' * markers
            + "execute as @e[tag=x] as @e[tag=x] run scoreboard players add @s o 1\n")

    emu = run_both(tmp_path, body)
    assert emu.backend.cints.shape[0] >= markers * markers > backend.CONTEXT_ROWS
    assert emu.backend.fstack.shape[0] > backend.FORK_ROWS
    assert sorted(emu.scores()["o"].values()) == [markers] * markers
