"""Numbers in entity NBT and command storage that the VM reads and writes itself: Pos, Motion,
Rotation and a display's transformation (columns of the entity table), and storage leaves
(emulator.vm.storage_leaves). Each form runs without a host op when the number is there, and
agrees with the reference backend, which saves the NBT, edits it and loads it back.

Sources (decompiled 1.21): server/commands/ExecuteCommand.java (storeData), server/commands/data/
DataCommands.java (getNumeric: Mth.floor; manipulateData: "Nothing changed"), world/entity/Entity.java
(load: Pos clamped, Motion over 10 dropped, Rotation's finite parts % 360), world/entity/Display.java
(readAdditionalSaveData: the transformation's floats), commands/arguments/NbtPathArgument.java
(CompoundChildNode.set, the root filter's compareNbt).
"""
from __future__ import annotations

import numpy as np
import pytest

from emulator.world.entities import entity_nbt
from tests.vm.helpers import emulator_for, host_kinds, run_both

SETUP = ("scoreboard objectives add o dummy\n"
         'summon item_display 0 0 0 {Tags:["d"],Rotation:[30f,10f],transformation:{translation:[0f,0.5f,0f],'
         'left_rotation:[0f,0f,0f,1f],scale:[0.25f,0.25f,0.25f],right_rotation:[0f,0f,0f,1f]}}\n'
         'summon marker 1 0 0 {Tags:["m"],Motion:[0.5d,0d,0d]}\n')


def _run_both(tmp_path, body: str):
    return run_both(tmp_path, SETUP + body)


def test_display_transformation_stores_and_reads_run_in_the_vm(tmp_path):
    emu = _run_both(tmp_path, "scoreboard players set #v o 7\n"
                              "execute as @e[tag=d] store result entity @s transformation.scale[0] float 0.125 run "
                              "scoreboard players get #v o\n"
                              "execute as @e[tag=d] store result entity @s transformation.left_rotation[-1] float -0.1 "
                              "run scoreboard players get #v o\n"
                              "execute as @e[tag=d] store result score #s o run data get entity @s "
                              "transformation.scale[0] 1000\n"
                              "execute as @e[tag=d] store result score #t o run data get entity @s "
                              "transformation.translation[1] 10\n"
                              "execute as @e[tag=d] store result score #r o run data get entity @s "
                              "transformation.left_rotation[3] 1000\n")
    assert [emu.score(h, "o") for h in ("#s", "#t", "#r")] == [875, 5, -700]
    t = entity_nbt(emu.state.entities.entities[0])["transformation"]
    assert t["scale"] == [0.875, 0.25, 0.25] and t["left_rotation"][3] == float(np.float32(7 * -0.1))
    assert sorted(host_kinds(emu)) == ["ObjectivesAdd", "Summon", "Summon"]  # the setup only


def test_rotation_and_motion_are_read_back_as_entity_load_reads_them(tmp_path):
    # Rotation: % 360 and an infinite part ignored; Motion: a component past 10 is dropped
    emu = _run_both(tmp_path, "scoreboard players set #v o 725\n"
                              "execute as @e store result entity @s Rotation[0] float 1 run scoreboard players get #v o\n"
                              "execute as @e store result entity @s Rotation[1] float 1000000000000000000000000000000000000000 run "
                              "scoreboard players get #v o\n"
                              "execute as @e store result score @s o run data get entity @s Rotation[0] 10\n"
                              "execute as @e store result entity @s Motion[1] double 0.001 run "
                              "scoreboard players get #v o\n"
                              "execute as @e[tag=m] store result entity @s Motion[2] double 0.1 run "
                              "scoreboard players get #v o\n"
                              "execute as @e[tag=m] store result score #m o run data get entity @s Motion[1] 1000\n")
    assert emu.score("#m", "o") == 725
    marker = emu.state.entities.entities[1]
    assert marker.motion == (0.5, 0.725, 0.0) and float(marker.yaw) == 5.0 and float(marker.pitch) == 0.0
    assert "Store" not in " ".join(host_kinds(emu))


@pytest.mark.parametrize("line", [
    "execute as @e[tag=m] store result entity @s transformation.scale[0] float 1 run scoreboard players get #v o",
    "execute as @e[tag=m] store result score #x o run data get entity @s transformation.scale[0]",
    "execute as @e[tag=d] store result entity @s Motion[0] int 1 run scoreboard players get #v o",
    "execute store result entity @s Rotation[0] float 1 run scoreboard players get #v o",
    "execute as @e[tag=d] store result score #x o run data get entity @s Rotation[5]",
])
def test_fields_an_entity_lacks_fail_as_in_the_reference(tmp_path, line):
    # a marker has no transformation; Motion holds doubles (an int does not fit the list); the
    # server has no entity; Rotation has two numbers
    _run_both(tmp_path, "scoreboard players set #v o 3\nscoreboard players set #x o 99\n" + line)


def test_storage_numbers_run_in_the_vm(tmp_path):
    body = ("data modify storage t:s flag set value 1b\n"  # the first: the host creates it
            "execute store success score #same o run data modify storage t:s flag set value 1b\n"
            "execute store result score #set o run data modify storage t:s flag set value 0b\n"
            "execute store success score #on o if data storage t:s {flag:1b}\n"
            "execute store success score #off o unless data storage t:s {flag:1b}\n"
            "scoreboard players set #v o -7\n"
            "data modify storage t:s n set value 0\n"
            "execute store result storage t:s n int 3 run scoreboard players get #v o\n"
            "execute store result score #n o run data get storage t:s n\n"
            "data modify storage t:s f set value 0f\n"
            "execute store result storage t:s f float 0.1 run scoreboard players get #v o\n"
            "execute store result score #f o run data get storage t:s f 100\n"
            "execute store result storage t:s b byte 1 run scoreboard players set #w o 300\n"
            "execute store result score #b o run data get storage t:s b\n"
            "data merge storage t:s {flag:1b}\n"
            "execute store success score #merged o if data storage t:s {flag:1b}\n")
    emu = _run_both(tmp_path, body)
    assert [emu.score(h, "o") for h in ("#same", "#set", "#on", "#off", "#n", "#f", "#b", "#merged")] == [
        0, 1, 0, 1, -21, -70, 44, 1]
    host = host_kinds(emu)
    # the three `set`s and the store into b that create their numbers, the merge
    assert host.count("DataModify") == 3 and host.count("DataMerge") == 1 and host.count("StoreData") == 1
    assert "IfData" not in host and "DataGet" not in host


def test_storage_paths_tested_in_the_vm(tmp_path):
    # ExecuteCommand.checkMatchingData: the count of tags the path finds (a key path: 0 or 1), any
    # tag type; a path through a list or a number finds nothing (NbtPathArgument.CompoundChildNode)
    body = ("data merge storage t:s {a:{b:[1,2],c:\"x\"},n:3}\n"
            "execute store result score #ab o if data storage t:s a.b\n"
            "execute store result score #ac o if data storage t:s a.c\n"
            "execute store result score #a o if data storage t:s a\n"
            "execute store result score #ad o if data storage t:s a.d\n"
            "execute store result score #nx o if data storage t:s n.x\n"
            "execute store result score #bx o if data storage t:s a.b.x\n"
            "execute store result score #not o unless data storage t:s a.d\n"
            "execute store result score #gone o if data storage t:other a\n"
            "execute if data storage t:s n run data remove storage t:s a.c\n"
            "execute store result score #ac2 o if data storage t:s a.c\n")
    emu = _run_both(tmp_path, body)
    assert [emu.score(h, "o") for h in ("#ab", "#ac", "#a", "#ad", "#nx", "#bx", "#not", "#gone", "#ac2")] == [
        1, 1, 1, 0, 0, 0, 1, 0, 0]
    host = host_kinds(emu)
    assert "IfData" not in host and host.count("DataRemove") == 1  # the VM reads the removal's result


def test_the_vm_reads_storage_changed_between_calls(tmp_path):
    from mcfunction_parser.nbt import Byte, Compound

    emu = emulator_for(tmp_path, {"t:main": "scoreboard objectives add o dummy\n"
                                            "execute store success score #on o if data storage t:s {flag:1b}"})
    emu.call("t:main")
    assert emu.score("#on", "o") == 0
    emu.state.storage["t:s"] = Compound(flag=Byte(1))
    emu.call("t:main")
    assert emu.score("#on", "o") == 1


# ---------------------------------------------------------------------- rotations and context stages
def test_tp_with_a_rotation_runs_in_the_vm(tmp_path):
    # TeleportCommand: `~` angles are relative to the execution rotation, then wrapDegrees and the
    # pitch clamped; an infinite angle is discarded (setYRot)
    emu = _run_both(tmp_path, "execute as @e[tag=d] run tp @s ~ ~ ~ ~180 ~\n"
                              "execute as @e[tag=d] at @s run tp @s ~ ~ ~ ~-370.5 ~95\n"
                              "tp @e[tag=m] 1 2 3 45 -100\n"
                              "execute as @e[tag=m] rotated as @s run tp @s ^ ^ ^1 ~ ~10\n"
                              "execute as @e[tag=d] run tp @s ~ ~ ~ 1000000000000000000000000000000000000000 0\n")
    display, marker = emu.state.entities.entities
    # `as` keeps the server's rotation: 0 + 180 wraps to -180; at @s: -180 - 370.5 wraps to 169.5;
    # the last yaw is infinite: kept, its pitch 0
    assert (float(display.yaw), float(display.pitch)) == (169.5, 0.0)
    assert (float(marker.yaw), float(marker.pitch)) == (45.0, -80.0)  # -90 (clamped) + 10
    assert not [n for n in host_kinds(emu) if n == "Teleport"]


def test_rotated_anchored_and_align_stages_run_in_the_vm(tmp_path):
    emu = _run_both(tmp_path, "execute as @e[tag=d] rotated ~10 ~-95 run tp @s ~ ~ ~ ~ ~\n"
                              "execute as @e[tag=m] at @s align xyz run tp @s ~0.25 ~ ~\n"
                              "execute as @e[tag=d] at @s anchored eyes positioned ^ ^ ^1 run tp @s ~ ~ ~\n"
                              "execute as @e[tag=m] at @s anchored eyes anchored feet rotated 90 0 run "
                              "tp @s ^ ^ ^2\n")
    assert sorted(host_kinds(emu)) == ["ObjectivesAdd", "Summon", "Summon"]


def test_a_teleport_to_another_level_is_charged_once(tmp_path):
    # OP_TP hands a target going to another level to the HOST after it: one command, one charge
    emu = _run_both(tmp_path, "execute in minecraft:the_end run tp @e[tag=m] ~ ~ ~ ~10 ~\n"
                              "execute in minecraft:the_nether run tp @e[tag=d] ~ ~ ~\n")
    assert emu.profile.functions_total["t:main"] == 3 + 2 * 2  # the setup's three, two chains of two


def test_list_elements_run_in_the_vm(tmp_path):
    # NbtPathArgument.IndexedElementNode: a negative index counts from the end, out of range finds
    # nothing; ListTag.setTag (before 1.21.5) keeps the list's element type
    body = ('data merge storage t:s {l:[1,2,3],m:[{x:1.5d},{x:2b}],e:[]}\n'
            "scoreboard players set #v o -7\n"
            "execute store result storage t:s l[0] int 3 run scoreboard players get #v o\n"
            "execute store result storage t:s m[-1].x byte 1 run scoreboard players set #w o 300\n"
            "execute store result score #l0 o run data get storage t:s l[0]\n"
            "execute store result score #l2 o run data get storage t:s l[-1] 10\n"
            "execute store result score #m0 o run data get storage t:s m[0].x 10\n"
            "execute store result score #m1 o run data get storage t:s m[-1].x\n"
            "execute store success score #set o run data modify storage t:s l[1] set value 5\n"
            "execute store success score #same o run data modify storage t:s l[1] set value 5\n"
            "execute store result score #has o if data storage t:s l[1]\n"
            "execute store result score #out o if data storage t:s l[3]\n"
            "execute store result score #neg o if data storage t:s l[-4]\n"
            "execute store result score #e o if data storage t:s e[0]\n"
            "execute store result score #mx o if data storage t:s m[-2]\n")
    emu = _run_both(tmp_path, body)
    assert [emu.score(h, "o") for h in ("#l0", "#l2", "#m0", "#m1", "#set", "#same", "#has", "#out", "#neg", "#e",
                                        "#mx")] == [-21, 30, 15, 44, 1, 0, 1, 0, 0, 0, 1]
    assert host_kinds(emu)[3:] == ["DataMerge"]  # after SETUP's


@pytest.mark.parametrize("line", [
    "execute store result storage t:s l[0] double 1 run scoreboard players get #v o",  # another type: the host's
    "data modify storage t:s l[-1] set value 2.5d",
    "execute store result storage t:s ia[0] double 1.5 run scoreboard players get #v o",  # an array converts
    "execute store result score #x o run data get storage t:s ia[1]",
    "execute store result storage t:s one[0] int 2 run scoreboard players get #v o",  # one[0] is one[-1]
    "data modify storage t:s l[-2] set value 7",  # l[-2] is l[0]
])
def test_list_elements_the_host_writes(tmp_path, line):
    body = ("data merge storage t:s {l:[1,2],ia:[I;5,6],one:[4]}\nscoreboard players set #v o 3\n" + line + "\n"
            "execute store result score #a o run data get storage t:s one[-1]\n"
            "execute store result score #b o run data get storage t:s l[0] 10\n")
    emu = _run_both(tmp_path, body)
    assert 6 in [run.node.loc.line for run in emu.backend.host_ops_run()]  # the line (after SETUP's 3, 2 more)
