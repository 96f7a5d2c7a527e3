"""Area effect clouds (``area_effect_cloud``: a lingering potion's, or summoned) tick as the server's
AreaEffectCloud.tick runs them.

- ``tick_clouds(state)``: every cloud's tick; ``tick_is_idle(state)``: no cloud (each one ages).

Each tick (decompiled 1.21 AreaEffectCloud.tick; ServerLevel.tickNonPassenger counts ``Age``, the
entity's tickCount, up first) a cloud whose ``Age`` reached ``WaitTime`` + ``Duration`` is gone
(what it read from its NBT: a missing ``Duration``, ``WaitTime`` or ``ReapplicationDelay`` is 0, a
missing ``Radius`` 3); while ``Age`` < ``WaitTime`` it waits; else ``RadiusPerTick`` grows its
radius (float), and under 0.5 it is gone. Every 5 ticks of ``Age`` it forgets the victims whose
delay ran out and, when its potion contents have effects, affects each living entity (not an armor
stand, not dying) whose box meets its own (2 x radius wide, 0.5 high) and whose feet are within the
radius horizontally, and that it has not affected within ``ReapplicationDelay`` ticks: each lasting
effect for a quarter of its duration (MobEffectInstance.mapDuration(d / 4)), each instant one at half
strength (applyInstantenousEffect(..., 0.5)); a player given one fires ``effects_changed`` with the
cloud as source. Each such use adds ``RadiusOnUse`` to the radius (gone under 0.5) and
``DurationOnUse`` to the duration (gone at 0 or less). Who it affected is not saved (the game keeps
it in memory too).

Not modelled (Unmodelled): a cloud's effects before 1.20.5 (``Potion``/``effects`` NBT) and from
1.21.5 (``potion_duration_scale``), the mobs immune to an effect (LivingEntity.canBeAffected); its
particles are nothing a pack reads.
"""
from __future__ import annotations

import numpy as np

from emulator.world import advancements, consumables, living, ray, thrown_hits
from emulator.world.errors import Unmodelled
from emulator.world.items import ItemStack
from emulator.world.nbt_ops import is_numeric, numeric_value
from mcfunction_parser.nbt import Compound, Float, Int

F32 = np.float32
CLOUD = "minecraft:area_effect_cloud"
COMPONENTS = (1, 20, 5)  # potion_contents
SCALED = (1, 21, 5)  # potion_duration_scale
MIN_RADIUS = F32(0.5)
EVERY = 5
HEIGHT = 0.5


def _is_cloud(entity_type: str) -> bool:
    return entity_type == CLOUD


def _clouds(state):
    clouds = state.entities.picked(CLOUD, _is_cloud)
    return [e for e in clouds if e.alive] if clouds else clouds


def tick_is_idle(state) -> bool:
    return not _clouds(state)


def tick_clouds(state) -> None:
    for cloud in _clouds(state):
        if cloud.alive:
            _tick(state, cloud)


def _number(data, key: str, default):
    value = data.get(key)
    return numeric_value(value) if is_numeric(value) else default


def _tick(state, cloud) -> None:
    data = cloud.data
    age = int(_number(data, "Age", 0)) + 1
    data["Age"] = Int(age)
    wait, duration = int(_number(data, "WaitTime", 0)), int(_number(data, "Duration", 0))
    if age >= wait + duration:
        state.discard(cloud)
        return
    if age < wait:
        return
    radius = F32(_number(data, "Radius", 3.0))
    per_tick = F32(_number(data, "RadiusPerTick", 0.0))
    if per_tick != 0:
        radius = F32(radius + per_tick)
        if radius < MIN_RADIUS:
            state.discard(cloud)
            return
        data["Radius"] = Float(float(radius))
    if age % EVERY == 0:
        _affect(state, cloud, age, radius)


def _affect(state, cloud, age: int, radius) -> None:
    victims = state.cloud_victims.setdefault(cloud, {})
    for entity in [e for e, until in victims.items() if age >= until]:
        del victims[entity]
    effects = _effects(state, cloud)
    if not effects:
        victims.clear()
        return
    data = cloud.data
    x, y, z = cloud.pos
    r = float(radius)
    box = (x - r, y, z - r, x + r, y + HEIGHT, z + r)
    source = thrown_hits.owner(state, cloud)
    for entity in [e for e in state.entities.entities if e.alive and e.dimension == cloud.dimension
                   and living.is_living(e.type) and ray.boxes_meet(box, e.bounding_box)]:
        if entity in victims or not thrown_hits.affected_by_potions(entity):
            continue
        dx, dz = entity.pos[0] - x, entity.pos[2] - z
        if dx * dx + dz * dz > float(radius) * float(radius):
            continue
        victims[entity] = age + int(_number(data, "ReapplicationDelay", 0))
        changed = False
        for effect_id, duration, amplifier in effects:
            if effect_id in living.INSTANT:
                thrown_hits.instant_effect(state, cloud, source, entity, effect_id, amplifier, 0.5)
            else:
                quarter = duration if duration == living.INFINITE else duration // 4
                changed |= living.give_effect(state, entity, effect_id, quarter, amplifier, True)
        if changed:
            advancements.effects_changed(state, entity, cloud)
        if not _used(state, cloud):
            return
        radius = F32(_number(data, "Radius", 3.0))


def _used(state, cloud) -> bool:
    """RadiusOnUse and DurationOnUse after a use; False when the cloud is gone."""
    data = cloud.data
    on_use = F32(_number(data, "RadiusOnUse", 0.0))
    if on_use != 0:
        radius = F32(F32(_number(data, "Radius", 3.0)) + on_use)
        if radius < MIN_RADIUS:
            state.discard(cloud)
            return False
        data["Radius"] = Float(float(radius))
    duration_on_use = int(_number(data, "DurationOnUse", 0))
    if duration_on_use != 0:
        duration = int(_number(data, "Duration", 0)) + duration_on_use
        data["Duration"] = Int(duration)
        if duration <= 0:
            state.discard(cloud)
            return False
    return True


def _effects(state, cloud) -> list:
    data = cloud.data
    version = tuple(state.version)
    if version < COMPONENTS:
        if any(key in data for key in ("Potion", "effects", "Effects")):
            raise Unmodelled("an area effect cloud's effects before 1.20.5")
        return []
    contents = data.get("potion_contents")
    if contents is None:
        return []
    if version >= SCALED:
        raise Unmodelled("an area effect cloud's effects from 1.21.5 (potion_duration_scale)")
    stack = ItemStack("minecraft:potion", 1, Compound({"minecraft:potion_contents": contents}))
    return consumables.potion_effects(stack, version)
