"""`anchored eyes` reads the executing entity's eye height as its pose, age and scale make it, the
same on both backends: `positioned ^ ^ ^` after it (the VM's jitted local coordinates read the
entity table's copy), `facing entity ... eyes` (the target's eyes) and `tp ... facing`.

Sources: commands/arguments/EntityAnchorArgument.java (Anchor.EYES: y + getEyeHeight()),
LocalCoordinates.getPosition, world/entity/player/Player.java (POSES: crouching eyes 1.27),
world/entity/monster/Zombie.java (BABY_DIMENSIONS: eyes 0.93), LivingEntity.getDimensions (the scale
attribute).
"""
from __future__ import annotations

import numpy as np
import pytest

from emulator.api import Emulator
from emulator.world import players, rotation
from tests.backends.programs import write_pack

F32 = np.float32
# (write_pack writes format 48, 1.21: the attribute is still named generic.scale)
MAIN = (
    "execute as @e[tag=a] at @s anchored eyes positioned ^ ^ ^ run summon marker ~ ~ ~ {Tags:[\"eyes\"]}\n"
    "attribute @e[type=zombie,tag=a,limit=1] minecraft:generic.scale base set 2\n"
    "execute as @e[tag=a] at @s anchored eyes positioned ^ ^ ^ run summon marker ~ ~ ~ {Tags:[\"scaled\"]}\n"
    'summon marker 0.5 70 3.5 {Tags:["looks"]}\n'
    "execute as @e[tag=looks] at @s facing entity @e[tag=a,limit=1] eyes run tp @s ~ ~ ~ ~ ~\n"
)


def run(backend: str, tmp_path, setup: str, sneaking: bool = False) -> Emulator:
    emu = Emulator(backend=backend)
    emu.load(write_pack(tmp_path / backend, {"t:main": setup + MAIN}))
    emu.add_player("Steve", (0.5, 64.0, 0.5))
    players.online(emu.state, "Steve").sneaking = sneaking
    emu.call("t:main")
    return emu


def heights(emu: Emulator, tag: str) -> list[float]:
    return [e["pos"][1] - 64.0 for e in emu.entities(f"@e[tag={tag}]")]


@pytest.mark.parametrize("setup, sneaking, eyes, scaled", [
    ("tag Steve add a\n", False, F32(1.62), F32(1.62)),
    ("tag Steve add a\n", True, F32(1.27), F32(1.27)),  # crouching
    ('summon zombie 0.5 64 0.5 {Tags:["a"],NoAI:1b}\n', False, F32(1.74), F32(1.74) * F32(2)),
    ('summon zombie 0.5 64 0.5 {Tags:["a"],IsBaby:1b,NoAI:1b}\n', False, F32(0.93), F32(0.93) * F32(2)),
    ('summon armor_stand 0.5 64 0.5 {Tags:["a"],Small:1b}\n', False, F32(0.9875), F32(0.9875)),
])
def test_anchored_eyes_follow_pose_age_and_scale(tmp_path, setup, sneaking, eyes, scaled):
    ref, vm = (run(backend, tmp_path, setup, sneaking) for backend in ("python", "numba"))
    assert vm.entities() == ref.entities()
    assert [d.format() for d in vm.diagnostics] == [d.format() for d in ref.diagnostics]
    assert heights(ref, "eyes") == [float(eyes)]
    assert heights(ref, "scaled") == [float(scaled)]
    [looks] = ref.entities("@e[tag=looks]")
    expected = rotation.facing_rotation((0.5, 70.0, 3.5), (0.5, 64.0 + float(scaled), 0.5))
    assert looks["rotation"] == [float(v) for v in expected]
