"""``data modify storage S P set from storage S2 P2`` between numbers the VM mirrors runs in the VM."""
from __future__ import annotations

from emulator.vm import loop as vm
from mcfunction_parser.nbt import to_snbt
from tests.vm.helpers import host_kinds, run_both

SETUP = "data merge storage t:s {a:1,b:2.5f,l:[1,2],m:[{x:1b}]}\n"


def test_a_copy_takes_the_source_type_and_fails_when_nothing_changes(tmp_path):
    """DataCommands.manipulateData: ``set`` puts a copy of the last tag found (NbtPathArgument.set,
    a float stays a float); the same tag already there changes nothing, which fails the command."""
    emu = run_both(tmp_path, SETUP + "data modify storage t:s a set from storage t:s b\n"
                   "execute store success storage t:s ok int 1 run data modify storage t:s a set from storage t:s b\n"
                   "data modify storage t:s l[1] set from storage t:s l[0]\n")
    assert to_snbt(emu.state.storage.get("t:s")) == "{a:2.5f,b:2.5f,l:[1,1],m:[{x:1b}],ok:0}"
    assert vm.OP_COPYLEAF in {row[0] for row in emu.backend.program.rows}
    assert "DataModify" not in host_kinds(emu)[1:]


def test_a_list_element_given_another_type_goes_to_the_host(tmp_path):
    """Before 1.21.5 a list holds one type (ListTag.setTag refuses another): the host reports it."""
    emu = run_both(tmp_path, SETUP + "data modify storage t:s m[0].x set from storage t:s a\n"
                   "data modify storage t:s l[0] set from storage t:s b\n")
    assert host_kinds(emu).count("DataModify") == 1  # the list element; a compound's key takes any type
