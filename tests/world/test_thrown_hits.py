"""Thrown item projectiles (eggs, ender pearls, experience bottles, potions) in flight and what
their hits do (emulator.world.projectile_flight, emulator.world.thrown_hits). Sources: decompiled
1.21 ThrowableProjectile.tick, Projectile.checkLeftOwner / canHitEntity, ThrownPotion (onHit,
applySplash, applyWater, makeAreaOfEffectCloud, getDefaultGravity), ThrownEgg.onHit,
ThrownEnderpearl.onHit, ThrownExperienceBottle (onHit, getDefaultGravity),
HealOrHarmMobEffect.applyInstantenousEffect."""
import copy
import math

import numpy as np
import pytest

from emulator import Emulator
from tests.conftest import write_pack
from tests.world.test_projectile_flight import world

F32 = np.float32
SLOWNESS_WITH_SPEED = ('{id:"splash_potion",components:{"minecraft:potion_contents":{potion:"minecraft:slowness",'
                       'custom_effects:[{id:"minecraft:speed",duration:100}]}}}')


def of_type(emu, type_id):
    return [e for e in emu.state.entities.entities if e.type == type_id and e.alive]


def effects(entity) -> dict:
    return {str(e["id"]): int(e["duration"]) for e in entity.data.get("active_effects", [])}


def unmodelled(emu):
    return [d.message for d in emu.diagnostics if d.unmodelled]


@pytest.mark.parametrize("type_id,gravity", [("egg", 0.03), ("ender_pearl", 0.03), ("experience_bottle", 0.07),
                                             ("potion", 0.05)])
def test_each_thrown_item_falls_by_its_own_gravity(tmp_path, type_id, gravity):
    # ThrowableProjectile.tick (1.21): move, then motion x 0.99F, then getDefaultGravity taken:
    # 0.03 (ThrowableProjectile), 0.05 (ThrownPotion), 0.07 (ThrownExperienceBottle)
    emu = world(tmp_path, f"summon {type_id} 0.5 100 0.5 {{Motion:[1.0d,0.0d,0.0d]}}\n")
    emu.tick()
    [thrown] = of_type(emu, "minecraft:" + type_id)
    assert thrown.pos == (1.5, 100.0, 0.5)
    assert thrown.motion == (float(F32(0.99)), -gravity, 0.0)


@pytest.mark.parametrize("backend", ["python", "numba"])
def test_a_splash_potion_gives_its_effects_scaled_by_distance(tmp_path, backend):
    # ThrownPotion.applySplash: the entity hit gets the full duration; another within 4 blocks
    # (int)((1 - distance / 4) x duration + 0.5), dropped when it ends within 20 ticks; one 4 or
    # more away nothing. In 1.21 the potion splashes from where it stood at the start of the tick.
    emu = world(tmp_path, "summon pig 0.5 10 0.5 {NoAI:1b,NoGravity:1b}\n"
                          "summon cow 3.5 10 0.5 {NoAI:1b,NoGravity:1b}\n"
                          "summon sheep 4.5 10 0.5 {NoAI:1b,NoGravity:1b}\n"
                          f"summon potion 0.5 12 0.5 {{Motion:[0.0d,-0.5d,0.0d],Item:{SLOWNESS_WITH_SPEED}}}\n",
                backend=backend)
    emu.tick(2)  # at 11.5 after the first tick; the second tick's segment enters the pig's box + 0.3
    assert not of_type(emu, "minecraft:potion")
    [pig], [cow], [sheep] = (of_type(emu, "minecraft:" + t) for t in ("pig", "cow", "sheep"))
    assert effects(pig) == {"minecraft:slowness": 1800, "minecraft:speed": 100}
    scale = 1.0 - math.sqrt(3.0 ** 2 + 1.5 ** 2) / 4.0
    assert effects(cow) == {"minecraft:slowness": int(scale * 1800 + 0.5)}  # speed: 16 ticks, within 20
    assert effects(sheep) == {}
    assert not unmodelled(emu)


def test_a_splash_potion_entity_type_of_1_21_5(tmp_path):
    # 1.21.5 split the thrown potion into splash_potion and lingering_potion entity types
    emu = world(tmp_path, "summon pig 0.5 10 0.5 {NoAI:1b,NoGravity:1b}\n"
                          f"summon splash_potion 0.5 12 0.5 {{Motion:[0.0d,-0.5d,0.0d],Item:{SLOWNESS_WITH_SPEED}}}\n",
                "1.21.5")
    emu.tick(3)
    [pig] = of_type(emu, "minecraft:pig")
    assert "minecraft:slowness" in effects(pig) and not of_type(emu, "minecraft:splash_potion")


def test_an_instant_effect_scales_its_amount(tmp_path):
    # HealOrHarmMobEffect.applyInstantenousEffect: (int)(scale x (6 << amplifier) + 0.5) hurt as
    # indirect magic: 6 to the pig hit, (int)(0.375 x 6 + 0.5) = 2 to the one 2.5 blocks away
    emu = world(tmp_path, "summon pig 0.5 10 0.5 {NoAI:1b,NoGravity:1b,Tags:[hit]}\n"
                          "summon pig 2.5 10 0.5 {NoAI:1b,NoGravity:1b}\n"
                          'summon potion 0.5 11.5 0.5 {Motion:[0.0d,-0.5d,0.0d],Item:{id:"splash_potion",'
                          'components:{"minecraft:potion_contents":"minecraft:harming"}}}\n')
    emu.tick()
    health = sorted(float(p.data["Health"]) for p in of_type(emu, "minecraft:pig"))
    assert health == [4.0, 8.0]


def test_a_lingering_potion_leaves_an_area_effect_cloud(tmp_path):
    # ThrownPotion.makeAreaOfEffectCloud: radius 3, -0.5 per use, 10 ticks waiting, shrinking by
    # radius / duration per tick, the potion contents
    emu = world(tmp_path, "fill -2 9 -2 2 9 2 stone\n"
                          'summon potion 0.5 10.2 0.5 {Motion:[0.0d,-0.5d,0.0d],Item:{id:"lingering_potion",'
                          'components:{"minecraft:potion_contents":"minecraft:poison"}}}\n')
    emu.tick()
    [cloud] = of_type(emu, "minecraft:area_effect_cloud")
    data = cloud.data
    assert cloud.pos == (0.5, 10.2, 0.5)
    assert (float(data["Radius"]), float(data["RadiusOnUse"]), int(data["WaitTime"])) == (3.0, -0.5, 10)
    assert float(data["RadiusPerTick"]) == float(-F32(3.0) / F32(600))
    assert str(data["potion_contents"]["potion"]) == "minecraft:poison"


def test_a_water_bottle_hurts_the_water_sensitive_and_puts_out_the_burning(tmp_path):
    # ThrownPotion.applyWater: a blaze (isSensitiveToWater) takes 1; a burning pig is put out
    emu = world(tmp_path, "summon blaze 0.5 10 0.5 {NoAI:1b,NoGravity:1b}\n"
                          "summon pig 2.5 10 0.5 {NoAI:1b,NoGravity:1b,Fire:200s}\n"
                          'summon potion 0.5 12.5 0.5 {Motion:[0.0d,-0.5d,0.0d],Item:{id:"splash_potion",'
                          'components:{"minecraft:potion_contents":"minecraft:water"}}}\n')
    emu.tick(2)
    [blaze], [pig] = of_type(emu, "minecraft:blaze"), of_type(emu, "minecraft:pig")
    assert float(blaze.data["Health"]) == 19.0
    assert int(pig.data["Fire"]) <= 0


def test_a_thrown_item_does_not_hit_its_owner_before_it_left_it(tmp_path):
    # Projectile.canHitEntity: not the owner (nor what rides with it) until checkLeftOwner finds
    # neither in the box stretched along the motion and inflated by 1 (LeftOwner)
    emu = world(tmp_path, "summon pig 0.5 10 0.5 {NoAI:1b,NoGravity:1b,UUID:[I;1,2,3,4]}\n"
                          "summon egg 0.5 10.4 0.5 {Motion:[1.0d,0.0d,0.0d],Owner:[I;1,2,3,4],NoGravity:1b}\n")
    emu.tick()
    [egg] = of_type(emu, "minecraft:egg")
    assert int(egg.data.get("LeftOwner", 0)) == 0
    emu.tick(2)
    assert int(egg.data["LeftOwner"]) == 1
    [pig] = of_type(emu, "minecraft:pig")
    assert float(pig.data["Health"]) == 10.0 and int(pig.data["HurtTime"]) == 0


def test_eggs_hatch_chicks_one_time_in_8_and_four_one_time_in_32(tmp_path):
    # ThrownEgg.onHit: nextInt(8) == 0 hatches one baby (Age -24000), four when nextInt(32) == 0;
    # drawn here from the emulator's seeded random, egg by egg
    eggs = "".join(f"summon egg {x}.5 10.5 0.5 {{Motion:[0.0d,-1.0d,0.0d]}}\n" for x in range(40))
    emu = world(tmp_path, "fill 0 9 0 39 9 0 stone\n" + eggs)
    rng = copy.deepcopy(emu.state.resources.random)
    emu.tick()
    expected = 0
    for _ in range(40):
        if rng.randrange(8) == 0:
            expected += 4 if rng.randrange(32) == 0 else 1
    chicks = of_type(emu, "minecraft:chicken")
    assert not of_type(emu, "minecraft:egg") and len(chicks) == expected > 0
    assert all(int(c.data["Age"]) == -24000 for c in chicks)


def test_an_ender_pearl_takes_its_owner_where_it_lands(tmp_path):
    # ThrownEnderpearl.onHit: the owner moves to the pearl (1.21: where it stood at the start of
    # its last tick), FallDistance 0; a player takes 5 fall damage
    emu = world(tmp_path, "fill 0 9 0 0 9 0 stone\n"
                          "summon pig 8.5 10 0.5 {NoAI:1b,NoGravity:1b,UUID:[I;1,2,3,4],FallDistance:3f}\n"
                          "summon ender_pearl 0.5 10.3 0.5 {Motion:[0.0d,-0.5d,0.0d],Owner:[I;1,2,3,4]}\n")
    emu.tick()
    [pig] = of_type(emu, "minecraft:pig")
    assert pig.pos == (0.5, 10.3, 0.5) and float(pig.data["FallDistance"]) == 0.0
    assert not of_type(emu, "minecraft:ender_pearl")


def test_an_ender_pearl_hurts_its_player_by_5(tmp_path):
    emu = Emulator(backend="python")
    emu.load([write_pack(tmp_path / "p", {"demo/function/f.mcfunction": (
        "fill 0 9 0 0 9 0 stone\nsummon ender_pearl 0.5 10.3 0.5 {Motion:[0.0d,-0.5d,0.0d]}\n"
        "data modify entity @e[type=ender_pearl,limit=1] Owner set from entity @p UUID\n")})], mc_version="1.21")
    emu.add_player("Alex", (8.5, 10.0, 0.5))
    emu.tick(60)  # past its spawn protection (ServerPlayer.spawnInvulnerableTime, up to 1.21.3)
    emu.call("demo:f")
    emu.tick()
    [player] = emu.state.entities.players()
    assert player.pos == (0.5, 10.3, 0.5) and float(player.data["Health"]) == 15.0


def test_an_experience_bottle_drops_3_to_11_points_of_orbs(tmp_path):
    # ThrownExperienceBottle.onHit: 3 + nextInt(5) + nextInt(5) points (ExperienceOrb.award's sizes)
    emu = world(tmp_path, "fill 0 9 0 0 9 0 stone\nsummon experience_bottle 0.5 10.3 0.5 {Motion:[0.0d,-0.5d,0.0d]}\n")
    rng = copy.deepcopy(emu.state.resources.random)
    emu.tick()
    points = 3 + rng.randrange(5) + rng.randrange(5)
    assert sum(int(o.data["Value"]) for o in of_type(emu, "minecraft:experience_orb")) == points


def test_a_lingering_potions_cloud_poisons_after_its_wait(tmp_path):
    # the cloud waits 10 ticks, then on Age 10 (a multiple of 5) gives a quarter of poison's 900
    emu = world(tmp_path, "fill -2 9 -2 2 9 2 stone\nsummon pig 1.5 10 0.5 {NoAI:1b}\n"
                          'summon potion 0.5 10.2 0.5 {Motion:[0.0d,-0.5d,0.0d],Item:{id:"lingering_potion",'
                          'components:{"minecraft:potion_contents":"minecraft:poison"}}}\n')
    emu.tick(10)  # the cloud is made on the first tick and first ticks on the next: Age 9
    [pig] = of_type(emu, "minecraft:pig")
    assert effects(pig) == {}
    emu.tick()
    assert effects(pig) == {"minecraft:poison": 225}
