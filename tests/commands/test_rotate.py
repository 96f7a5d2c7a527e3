"""``rotate`` (1.21.2+): the entity's rotation, on both backends.
Sources: server/commands/RotateCommand.java (rotate(source, entity, Coordinates): the rotation
argument against the execution rotation, Entity.forceSetRotation -> setYRot/setXRot, neither
wrapped nor clamped; rotate(source, entity, LookAt): LookAt.perform -> Entity.lookAt from the
entity's position, as ``tp ... facing``); the result is 1, an empty target fails."""
import pytest

from tests.world.world_emulator import emulator

PACK_FORMAT_1_21_4 = 61


def emulator_1_21_4(tmp_path, backend, functions):
    return emulator(tmp_path, backend, functions, pack_format=PACK_FORMAT_1_21_4)


def rotation(emu, tag):
    return [e["rotation"] for e in emu.entities() if tag in e["tags"]][0]


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_rotate_sets_what_tp_with_a_rotation_would_not_wrap(tmp_path, backend):
    emu = emulator_1_21_4(tmp_path, backend, {"t:go": "\n".join([
        "summon marker 0 0 0 {Tags:[\"a\"]}",
        "summon marker 0 0 0 {Tags:[\"b\"]}",
        "summon marker 0 0 0 {Tags:[\"c\"]}",
        "summon marker 3 0 4 {Tags:[\"d\"]}",
        "summon marker 0 0 0 {Tags:[\"e\"],Rotation:[10f,5f]}",
        "execute store result score #abs o run rotate @e[tag=a,limit=1] 200 120",
        # ~ is the execution rotation (rotated 30 10), not the entity's own
        "execute rotated 30 10 run rotate @e[tag=b,limit=1] ~15 ~",
        "execute store result score #pos o run rotate @e[tag=c,limit=1] facing 0 1 1",
        "execute store result score #ent o run rotate @e[tag=c,limit=1] facing entity @e[tag=d,limit=1] feet",
        "execute store success score #none o run rotate @e[tag=nobody,limit=1] 0 0",
        # the same angles through tp: wrapped and clamped
        "tp @e[tag=e] 0 0 0 200 120",
        "execute as @e[tag=d] run rotate @s facing 3 0 5",
    ])})
    emu.call("t:go")
    assert [emu.score(h, "o") for h in ("#abs", "#pos", "#ent", "#none")] == [1, 1, 1, 0]
    assert rotation(emu, "a") == [200.0, 120.0]
    assert rotation(emu, "b") == [45.0, 10.0]
    yaw, pitch = rotation(emu, "c")  # towards (3, 0, 4) from (0, 0, 0): Mth.atan2(4, 3) - 90 (a table's approximation)
    assert yaw == pytest.approx(-36.8699, abs=1e-3) and pitch == 0.0
    assert rotation(emu, "e") == [-160.0, 90.0]
    assert rotation(emu, "d") == pytest.approx([0.0, 0.0], abs=1e-4)  # due south, level


def test_rotate_agrees_on_both_backends(tmp_path):
    text = "\n".join([
        "summon armor_stand 1.3 2 -0.7 {Tags:[\"s\"]}",
        "summon pig 4 0 2 {Tags:[\"p\"]}",
        "execute as @e[tag=s] at @s anchored eyes run rotate @s facing entity @e[tag=p,limit=1] eyes",
        "execute as @e[tag=p] at @s rotated 17.3 -4.1 run rotate @s ~0.37 ~-91",
    ])
    seen = []
    for backend in ("numba", "python"):
        emu = emulator_1_21_4(tmp_path / backend, backend, {"t:go": text})
        emu.call("t:go")
        seen.append([rotation(emu, tag) for tag in ("s", "p")])
    assert seen[0] == seen[1] and seen[0][1] == pytest.approx([17.67, -95.1])
