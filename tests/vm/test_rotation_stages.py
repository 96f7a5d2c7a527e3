"""Rotations the VM computes itself: ``execute facing X Y Z`` and ``facing entity SEL feet|eyes``
(the game's table-based Mth.atan2, compiled from the same source the reference runs).

Sources (decompiled 1.21): commands/CommandSourceStack.java (facing: from the anchor position,
pitch = wrapDegrees((float) -(atan2(dy, horizontal) * 180/PI)), yaw = wrapDegrees((float)(atan2(dz,
dx) * 180/PI) - 90)), commands/arguments/EntityAnchorArgument.java (Anchor.apply: feet, or the
eyes), server/commands/ExecuteCommand.java (facing: a redirect; facing entity: a fork over the
entities found), util/Mth.java (atan2, fastInvSqrt).
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
