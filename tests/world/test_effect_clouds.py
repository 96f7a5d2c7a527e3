"""Area effect clouds (emulator.world.effect_clouds). Sources: decompiled 1.21 AreaEffectCloud.tick
(age, wait, radius per tick, every 5 ticks the victims, a quarter of each duration, radius and
duration on use, the reapplication delay), readAdditionalSaveData (missing ints are 0, the radius 3),
ServerLevel.tickNonPassenger (tickCount, saved as Age, counts up before the tick)."""
import numpy as np
import pytest

from tests.world.test_projectile_flight import world

F32 = np.float32
POISON_CLOUD = ('summon area_effect_cloud 0.5 10 0.5 {Duration:100,ReapplicationDelay:20,RadiusOnUse:-0.5f,'
                'DurationOnUse:-10,potion_contents:{potion:"minecraft:poison"}}\n')


def clouds(emu):
    return [e for e in emu.state.entities.entities if e.type == "minecraft:area_effect_cloud" and e.alive]


def poison(entity):
    return {str(e["id"]): int(e["duration"]) for e in entity.data.get("active_effects", [])}.get("minecraft:poison")


@pytest.mark.parametrize("backend", ["python", "numba"])
def test_a_cloud_lives_wait_time_plus_duration_ticks(tmp_path, backend):
    # readAdditionalSaveData: no Duration or WaitTime is 0, so a bare cloud is gone at its first tick
    emu = world(tmp_path, "summon area_effect_cloud 0.5 10 0.5\n"
                          "summon area_effect_cloud 2.5 10 0.5 {Duration:5,WaitTime:2}\n", backend=backend)
    emu.tick()
    [cloud] = clouds(emu)
    assert int(cloud.data["Age"]) == 1
    emu.tick(5)
    assert clouds(emu) == [cloud]
    emu.tick()  # Age 7 >= 2 + 5
    assert clouds(emu) == []


def test_a_cloud_shrinks_by_its_radius_per_tick_and_is_gone_under_half_a_block(tmp_path):
    emu = world(tmp_path, "summon area_effect_cloud 0.5 10 0.5 {Duration:100,Radius:1.0f,RadiusPerTick:-0.25f}\n")
    emu.tick(2)
    [cloud] = clouds(emu)
    assert float(cloud.data["Radius"]) == 0.5
    emu.tick()
    assert clouds(emu) == []


def test_a_cloud_gives_a_quarter_of_its_effects_to_who_stands_in_it_every_5_ticks(tmp_path):
    # poison 900 ticks -> 225; the pig at the corner meets the cloud's box but stands 4.1 away
    emu = world(tmp_path, "summon pig 2.5 10 0.5 {NoAI:1b,NoGravity:1b,Tags:[near]}\n"
                          "summon pig 3.4 10 3.4 {NoAI:1b,NoGravity:1b,Tags:[far]}\n" + POISON_CLOUD)
    near, far = sorted((e for e in emu.state.entities.entities if e.type == "minecraft:pig"), key=lambda e: e.pos[2])
    emu.tick(4)
    assert poison(near) is None
    emu.tick()  # Age 5
    assert poison(near) == 225 and poison(far) is None
    [cloud] = clouds(emu)
    assert float(cloud.data["Radius"]) == 2.5 and int(cloud.data["Duration"]) == 90  # on use


def test_a_cloud_affects_the_same_entity_again_only_after_its_reapplication_delay(tmp_path):
    emu = world(tmp_path, "summon pig 1.5 10 0.5 {NoAI:1b,NoGravity:1b}\n" + POISON_CLOUD)
    [pig] = [e for e in emu.state.entities.entities if e.type == "minecraft:pig"]
    emu.tick(5)
    pig.data["active_effects"].clear()
    emu.tick(15)  # Age 20: the victim waits until 5 + 20
    assert poison(pig) is None
    emu.tick(5)  # Age 25
    assert poison(pig) == 225
