"""A hurt's knockback (emulator.world.combat._hurt_knockback, emulator.world.living.knockback), read
exactly through the API on both backends. Sources (decompiled 1.21): LivingEntity.hurtServer (the
knockback of a full hurt, unless the type is in #no_knockback: 0.4F towards -(source position -
the entity's), a projectile's flight direction), LivingEntity.knockback, DamageSource.
getSourcePosition (the given position, else the direct entity's), DamageCommand (``at``, ``by``)."""
import pytest

from tests.world.world_emulator import emulator

BACKENDS = ["numba", "python"]
STRENGTH = 0.4000000059604645  # (double) 0.4F
FLOOR = "fill -3 0 -3 6 0 6 stone\n"
ZOMBIE = "summon zombie 0.5 1 0.5 {Tags:[\"z\"],OnGround:1b,Motion:[0.0d,0.0d,0.0d],PersistenceRequired:1b}\n"


def world(tmp_path, backend, commands):
    emu = emulator(tmp_path, backend, {"t:go": FLOOR + ZOMBIE + commands})
    emu.call("t:go")
    [zombie] = [e for e in emu.state.entities.entities if e.type == "minecraft:zombie"]
    return emu, zombie


def unmodelled(emu):
    return [d.message for d in emu.state.diagnostics if d.unmodelled]


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_hurt_by_an_entity_knocks_the_mob_away_from_it(tmp_path, backend):
    # the marker 2 blocks east: (x, z) = (2, 0), normalised and scaled by 0.4F; on the ground the
    # motion's y becomes min(0.4, y / 2 + 0.4F)
    emu, zombie = world(tmp_path, backend, (
        "summon marker 2.5 1 0.5 {Tags:[\"src\"]}\n"
        "damage @e[tag=z,limit=1] 2 minecraft:mob_attack by @e[tag=src,limit=1]"))
    assert zombie.motion == (-STRENGTH, 0.4, 0.0)
    assert not unmodelled(emu)
    emu.tick()
    assert zombie.pos[0] < 0.5  # it moves by that motion from the next tick


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_hurt_at_a_position_knocks_from_there_less_the_resistance(tmp_path, backend):
    # ``at``: the source position (Vec3Argument centres 0 and 5: 0.5, 5.5); the knockback_resistance
    # attribute takes its share of the strength; the motion before is halved
    emu, zombie = world(tmp_path, backend, (
        "attribute @e[tag=z,limit=1] generic.knockback_resistance base set 0.25\n"
        "data modify entity @e[tag=z,limit=1] Motion set value [0.2d,0.0d,0.0d]\n"
        "damage @e[tag=z,limit=1] 2 minecraft:mob_attack at 0 1 5"))
    strength = STRENGTH * (1.0 - 0.25)
    assert zombie.motion == (0.1, min(0.4, strength), -strength)


@pytest.mark.parametrize("backend", BACKENDS)
def test_no_knockback_for_no_knockback_types_a_second_hurt_in_the_cooldown_or_an_armor_stand(tmp_path, backend):
    # #no_knockback (generic is in it); within 10 ticks of a full hurt only the excess counts and
    # there is no knockback (tookFullDamage false); ArmorStand's own hurt has none
    emu, zombie = world(tmp_path, backend, (
        "summon marker 2.5 1 0.5 {Tags:[\"src\"]}\n"
        "summon armor_stand 0.5 1 3.5 {Tags:[\"stand\"]}\n"
        "damage @e[tag=z,limit=1] 2\n"
        "damage @e[tag=z,limit=1] 3 minecraft:mob_attack by @e[tag=src,limit=1]\n"
        "damage @e[tag=stand,limit=1] 1 minecraft:mob_attack by @e[tag=src,limit=1]"))
    [stand] = [e for e in emu.state.entities.entities if e.type == "minecraft:armor_stand"]
    assert zombie.motion == (0.0, 0.0, 0.0) and stand.motion == (0.0, 0.0, 0.0)
    assert 17.0 < float(zombie.data["Health"]) < 18.0  # the second took its excess (1, less the armour)


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_knockback_in_a_random_direction_is_reported_not_modelled(tmp_path, backend):
    # no source position (or the source where the mob stands): LivingEntity.knockback draws the
    # direction from Math.random, which no pack can reproduce; the hurt itself is done
    emu, zombie = world(tmp_path, backend, "damage @e[tag=z,limit=1] 2 minecraft:mob_attack")
    assert zombie.motion == (0.0, 0.0, 0.0) and float(zombie.data["Health"]) < 20.0
    assert unmodelled(emu) == ["the knockback of Zombie's hurt in a random direction (no source position)"]
