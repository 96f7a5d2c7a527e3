"""How the backend resumes the VM: ``run`` takes the machine by its address and type (unboxing the
structref read its ``_meminfo`` by name on every resume), through its compiled entry point; a plain
function standing in for ``run`` (bench/run.py's timer of the VM's share of a tick) gets the same
arguments and calls the dispatcher with them."""
from __future__ import annotations

from tests.vm.helpers import SETUP, emulator_for

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
