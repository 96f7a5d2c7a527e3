"""Entities on fire (emulator.world.burning) and burning arrows. Sources: decompiled 1.21
Entity.baseTick (the fire countdown, on_fire hurt each 20 ticks, fire-immune types losing 4),
Entity.updateInWaterStateAndDoWaterCurrentPushing (water clears the fire), Entity.isOnFire,
LivingEntity.hurt (fire resistance), AbstractArrow.onHitEntity (a burning arrow ignites for 5 s)."""
import pytest

from tests.world.test_projectile_flight import world
from tests.conftest import write_pack
from emulator import Emulator


def only(emu, type_id):
    [found] = [e for e in emu.state.entities.entities if e.type == type_id and e.alive]
    return found


def state_of(entity):
    return int(entity.data["Fire"]), float(entity.data["Health"])


@pytest.mark.parametrize("backend", ["python", "numba"])
def test_fire_counts_down_and_hurts_by_1_each_20_ticks(tmp_path, backend):
    # Entity.baseTick: hurt (on_fire, 1) when Fire % 20 == 0, then Fire - 1
    emu = world(tmp_path, "summon pig 0.5 10 0.5 {NoAI:1b,NoGravity:1b,Fire:41s}\n", backend=backend)
    emu.tick()
    assert state_of(only(emu, "minecraft:pig")) == (40, 10.0)
    emu.tick()
    assert state_of(only(emu, "minecraft:pig")) == (39, 9.0)
    emu.tick(40)  # hurt again at 20; at 0 it no longer burns (Fire > 0)
    assert state_of(only(emu, "minecraft:pig")) == (0, 8.0)


def test_a_fire_immune_mob_loses_4_ticks_and_is_not_hurt(tmp_path):
    # Entity.baseTick: fireImmune (EntityType.fireImmune: blaze) -> Fire - 4, cleared to 0 below 0
    emu = world(tmp_path, "summon blaze 0.5 10 0.5 {NoAI:1b,NoGravity:1b,Fire:10s}\n")
    emu.tick()
    assert state_of(only(emu, "minecraft:blaze")) == (6, 20.0)
    emu.tick(2)
    assert state_of(only(emu, "minecraft:blaze")) == (0, 20.0)


def test_fire_resistance_stops_the_fire_hurt(tmp_path):
    emu = world(tmp_path, "summon pig 0.5 10 0.5 {NoAI:1b,NoGravity:1b,Fire:20s}\n"
                          "effect give @e[type=pig] fire_resistance 10\n")
    emu.tick()
    assert state_of(only(emu, "minecraft:pig")) == (19, 10.0)


def test_water_puts_a_burning_mob_out(tmp_path):
    # updateInWaterStateAndDoWaterCurrentPushing: in water (a source's top 8/9 above the feet) clearFire
    emu = world(tmp_path, "setblock 0 10 0 water\nsummon pig 0.5 10.5 0.5 {NoAI:1b,NoGravity:1b,Fire:100s}\n"
                          "summon pig 5.5 10.9 0.5 {NoAI:1b,NoGravity:1b,Fire:100s,Tags:[dry]}\n"
                          "setblock 5 10 0 water\n")
    emu.tick()
    wet, dry = sorted(emu.state.entities.entities, key=lambda e: e.pos[0])
    assert state_of(wet) == (0, 10.0)
    assert state_of(dry) == (99, 9.0)  # feet above the water's top (10 + 8/9): still burning


def test_the_on_fire_flag_is_the_servers(tmp_path):
    # EntityFlagsPredicate.is_on_fire -> Entity.isOnFire on the server: Fire > 0 and not fire
    # immune; HasVisualFire only shows on clients
    emu = Emulator(backend="python")
    emu.load([write_pack(tmp_path / "p", {
        "demo/predicate/burning.json": '{"condition":"minecraft:entity_properties","entity":"this",'
                                       '"predicate":{"flags":{"is_on_fire":true}}}',
        "demo/function/f.mcfunction": "summon pig 0 10 0 {NoAI:1b,Fire:100s,Tags:[a]}\n"
                                      "summon blaze 2 10 0 {NoAI:1b,Fire:100s,Tags:[b]}\n"
                                      "summon pig 4 10 0 {NoAI:1b,HasVisualFire:1b,Tags:[c]}\n"
                                      "execute as @e if predicate demo:burning run tag @s add burning\n"})],
             mc_version="1.21")
    emu.call("demo:f")
    burning = {str(t) for e in emu.state.entities.entities if "burning" in e.tags for t in e.tags} - {"burning"}
    assert burning == {"a"}


@pytest.mark.parametrize("fire,ignited", [(100, 100), (-1, -1)])
def test_a_burning_arrow_sets_what_it_hits_on_fire(tmp_path, fire, ignited):
    # AbstractArrow.onHitEntity: isOnFire -> the target igniteForSeconds(5) = 100 ticks, then hurt
    emu = world(tmp_path, "summon pig 3.5 10 0.5 {NoAI:1b,NoGravity:1b}\n"
                          f"summon arrow 0.5 10.5 0.5 {{Motion:[1.0d,0.0d,0.0d],Fire:{fire}s}}\n")
    emu.tick(3)
    pig = only(emu, "minecraft:pig")
    assert state_of(pig) == (ignited, 8.0)
    assert not [d for d in emu.diagnostics if d.unmodelled]
