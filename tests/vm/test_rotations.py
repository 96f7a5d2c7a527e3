"""Rotations the VM computes itself: ``execute facing X Y Z`` and ``facing entity SEL feet|eyes``,
``tp ... facing`` (the game's table-based Mth.atan2, compiled from the same source the reference
runs), and ``tp`` to an entity.

Sources (decompiled 1.21): commands/CommandSourceStack.java (facing: from the anchor position,
pitch = wrapDegrees((float) -(atan2(dy, horizontal) * 180/PI)), yaw = wrapDegrees((float)(atan2(dz,
dx) * 180/PI) - 90)), commands/arguments/EntityAnchorArgument.java (Anchor.apply: feet, or the
eyes), server/commands/ExecuteCommand.java (facing: a redirect; facing entity: a fork over the
entities found), util/Mth.java (atan2, fastInvSqrt), server/commands/TeleportCommand.java (teleportToEntity: the
destination's position and rotation; LookAtPosition/LookAtEntity.perform: Entity.lookAt(the source's
anchor, target) after the move), world/entity/Entity.java (lookAt: from the entity's own anchor).
"""
from __future__ import annotations

import math
import struct

import numpy as np
import pytest

from emulator.vm import loop
from emulator.world import rotation
from tests.vm.helpers import host_kinds, run_both

SETUP = ("scoreboard objectives add o dummy\n"
         'summon marker 1 2 3 {Tags:["m"],Rotation:[10f,20f]}\n'
         'summon armor_stand -4 0.5 7 {Tags:["m","s"]}\n'
         'summon marker 0.3 -2 5.5 {Tags:["n"]}\n')


def _bits(x: float) -> int:
    return struct.unpack("<q", struct.pack("<d", x))[0]


def test_the_compiled_atan2_is_the_python_one_bit_for_bit():
    """Mth.atan2 in the VM (its double bit casts as LLVM bitcasts) against mth.atan2, itself checked
    against the JVM in tests/world/test_mth.py."""
    rng = np.random.default_rng(7)
    values = [0.0, -0.0, 1.0, -1.0, 1e-300, -1e-300, 1e300, 3.5, -2.25, math.inf, -math.inf, math.nan]
    values += list(rng.normal(0, 10, 300)) + list(rng.normal(0, 1e6, 100))
    pairs = [(y, x) for y in values[:40] for x in values[:40]] + list(zip(values, values[::-1]))
    for y, x in pairs:
        ours, theirs = loop._facing_angles(x, y, -x), rotation.facing_angles(x, y, -x)
        assert [_bits(float(a)) if not math.isnan(a) else "nan" for a in ours] == \
            [_bits(float(a)) if not math.isnan(a) else "nan" for a in theirs], (x, y)


def test_facing_a_position_turns_the_context(tmp_path):
    # from (0, 0, 0) to (1, 0, 1): yaw atan2(1, 1) - 90 = -45, pitch 0 (to the game's float)
    emu = run_both(tmp_path, SETUP + "execute as @e[tag=n] positioned 0 0 0 facing 1 0 1 run tp @s ~ ~ ~ ~ ~\n")
    yaw, pitch = emu.entities("@e[tag=n]")[0]["rotation"]
    assert (round(yaw, 4), pitch) == (-45.0, 0.0)
    assert not set(host_kinds(emu)) & {"ExFacing", "Teleport"}  # both ran in the VM


@pytest.mark.parametrize("chain", [
    "as @e[tag=m] at @s facing 0 0 0",  # world coordinates
    "as @e[tag=s] at @s anchored eyes facing ^1 ^2 ^3",  # local ones, from the eyes
    "as @e[tag=s] at @s anchored eyes facing ~ ~5 ~-1",  # the anchor raises the origin only
    "as @e[tag=n] at @s facing entity @e[tag=m] eyes",  # a fork: one context per entity
    "as @e[tag=n] at @s facing entity @e[tag=s] feet",
    "as @e[tag=m] at @s anchored eyes facing entity @e[tag=n,limit=1] eyes",
    "as @e[tag=m] at @s facing entity @s feet",  # its own position: atan2(0, 0)
    "facing entity @e[tag=nobody] eyes",  # no entity: no context
])
def test_facing_stages_run_in_the_vm(tmp_path, chain):
    emu = run_both(tmp_path, SETUP + f'execute {chain} run summon marker ~ ~ ~ {{Tags:["f"]}}\n'
                              "execute as @e[tag=f] at @s run tp @s ~ ~ ~ ~ ~\n"
                              f"execute store result score #n o {chain} run scoreboard players add #c o 1\n")
    assert not set(host_kinds(emu)) & {"ExFacing", "ExFacingEntity", "Teleport"}


@pytest.mark.parametrize("line", [
    "execute as @e[tag=m] at @s run tp @s ~1 ~ ~ facing 0 0 0",
    "execute as @e[tag=n] at @s anchored eyes run tp @e[tag=m] ~ ~1 ~ facing entity @n[tag=n] eyes",
    "tp @e[tag=m] 0 1 0 facing entity @n[tag=n] feet",
    "execute anchored eyes run tp @e[type=armor_stand] ^ ^ ^1 facing ~1 ~ ~",  # from its own eyes
    "tp @e[tag=n] @n[type=armor_stand]",  # its position and rotation
    "execute as @e[tag=m] run tp @e[tag=n,limit=1]",
    "tp @e[tag=m] ~ ~ ~ facing entity @e[tag=nobody,limit=1] eyes",  # no entity to face: fails
    "tp @e[tag=n] @e[tag=nobody,limit=1]",
    "tp @e[tag=n] @e[tag=m,sort=furthest,limit=1]",
])
def test_teleports_facing_or_to_an_entity_run_in_the_vm(tmp_path, line):
    emu = run_both(tmp_path, SETUP + f"execute store result score #r o run {line}\n")
    assert not set(host_kinds(emu)) & {"Teleport"}


def test_a_teleport_facing_turns_each_target_from_its_own_anchor(tmp_path):
    # two entities at the same place facing one point from their eyes: the armor stand's eyes are
    # higher than the marker's (its eye height 1.7875, a marker's 0), so it looks down more
    emu = run_both(tmp_path, SETUP + "execute anchored eyes run tp @e[tag=m] 0 0 0 facing 5 0 0\n")
    (_, marker_pitch), (_, stand_pitch) = [e["rotation"] for e in emu.entities("@e[tag=m]")]
    assert marker_pitch == 0.0 and stand_pitch > 19.0
    assert not set(host_kinds(emu)) & {"Teleport"}


def test_a_teleport_to_an_entity_in_another_level_runs_on_the_host(tmp_path):
    emu = run_both(tmp_path, SETUP + 'execute in minecraft:the_nether run summon marker 0 0 0 {Tags:["x"]}\n'
                                     "tp @e[tag=n] @n[tag=x]\n")
    assert emu.entities("@e[tag=n]")[0]["dimension"] == "minecraft:the_nether"
    assert "Teleport" in host_kinds(emu)
