"""What a thrown item projectile does when it hits (its ``onHit``/``onHitEntity``), once
:mod:`emulator.world.projectile_flight` found the entity or block in its way.

- ``hit(state, projectile, target)``: the hit of a snowball, egg, ender pearl, experience bottle or
  potion on ``target`` (an entity) or on a block (``target`` None); the projectile is gone after.

Per type (decompiled 1.21; the 1.21.5 split of ``potion`` into ``splash_potion`` and
``lingering_potion`` entity types only renames what decides a lingering one):
- a snowball, egg or ender pearl hurts the living entity it hits by 0 (a snowball 3 to a blaze)
  as ``thrown`` damage its owner is responsible for (HurtTime, ``player_hurt_entity`` with the
  projectile as direct entity: Snowball/ThrownEgg/ThrownEnderpearl.onHitEntity);
- an egg hatches one baby chicken (Age -24000) one time in 8 and then four one time in 32
  (ThrownEgg.onHit: ``random.nextInt(8) == 0``, ``random.nextInt(32) == 0``), drawn from the
  emulator's seeded random (the game draws from the egg's own unseeded random), at the egg with
  its yaw;
- an ender pearl moves its owner (alive, in the pearl's dimension) to the pearl, off its vehicle,
  ``FallDistance`` 0; a player owner takes 5 ``fall`` damage and, one time in 20 with
  ``doMobSpawning``, an endermite appears where the player was (ThrownEnderpearl.onHit);
- an experience bottle drops 3 + nextInt(5) + nextInt(5) points as orbs (ThrownExperienceBottle,
  ExperienceOrb.award: :func:`emulator.world.combat.award_orbs`);
- a splash potion gives each living entity affected by potions whose box meets the potion's
  inflated by 4, 2, 4 and that stands within 4 blocks of it its effects scaled by
  ``1 - distance / 4`` (1 for the entity hit): a lasting effect's duration becomes
  ``(int)(scale x duration + 0.5)`` and is dropped when it would end within 20 ticks, an instant
  effect's amount becomes ``(int)(scale x (4 << amplifier) + 0.5)`` healed or
  ``(int)(scale x (6 << amplifier) + 0.5)`` hurt as ``indirect_magic`` (ThrownPotion.applySplash,
  HealOrHarmMobEffect.applyInstantenousEffect); a player given one fires ``effects_changed``
  with the owner (else the potion) as source;
- a water bottle (potion ``minecraft:water``, splash or lingering) hurts each water-sensitive
  living entity in that range by 1 (``indirect_magic``) and puts out each burning one
  (ThrownPotion.applyWater);
- a lingering potion leaves an ``area_effect_cloud`` at the potion (Radius 3, RadiusOnUse -0.5,
  WaitTime 10, RadiusPerTick -3/600, Duration 600, ReapplicationDelay 20, its potion contents, its
  living owner: ThrownPotion.makeAreaOfEffectCloud), which then ticks
  (:mod:`emulator.world.effect_clouds`).

Not modelled (raise Unmodelled, the test is inconclusive): hitting an entity that is not living
(boats, frames, crystals: its own hurt), an egg's chick that would be inside a block
(fudgePositionAfterSizeChange), an ender pearl owner in another dimension or sleeping, a water
bottle's block hit that would put out fire, candles or campfires (dowseFire) or its axolotls'
rehydration, a potion's ``potion_duration_scale`` (1.21.5+), the mobs immune to an effect
(LivingEntity.canBeAffected) and an experience orb merging into one nearby (entity ids).
"""
from __future__ import annotations

import math

import numpy as np

from emulator.world import advancements, block_shapes, combat, consumables, living, ray
from emulator.world.errors import Unmodelled
from emulator.world.items import from_nbt
from emulator.world.loot_context import DamageSource
from emulator.world.nbt_ops import is_numeric, numeric_value
from emulator.world.relations import stop_riding
from mcfunction_parser.nbt import Compound, Float, Int, IntArray, Short, String

F32 = np.float32
POTIONS = frozenset(("minecraft:potion", "minecraft:splash_potion", "minecraft:lingering_potion"))
SPLASH_RANGE = 4.0  # ThrownPotion.SPLASH_RANGE
PEARL_FALL_DAMAGE = 5.0
ENDERMITE_CHANCE = 0.05
# LivingEntity.isSensitiveToWater: hurt by a water bottle
WATER_SENSITIVE = frozenset("minecraft:" + n for n in ("enderman", "blaze", "snow_golem", "strider"))
# makeAreaOfEffectCloud over a new cloud's fields (duration 600, reapplicationDelay 20)
_CLOUD = dict(Radius=3.0, RadiusOnUse=-0.5, WaitTime=10, Duration=600, ReapplicationDelay=20)


def hit(state, projectile, target, cell=None) -> None:
    """The projectile's onHit on ``target`` (an entity) or on the block at ``cell`` (target None);
    it is gone after."""
    kind = projectile.type
    if target is not None and kind not in POTIONS and kind != "minecraft:experience_bottle":
        _thrown_hurt(state, projectile, target)
    if kind == "minecraft:egg":
        _hatch(state, projectile)
    elif kind == "minecraft:ender_pearl":
        _teleport_owner(state, projectile)
    elif kind == "minecraft:experience_bottle":
        rng = state.resources.random
        combat.award_orbs(state, projectile.pos, 3 + rng.randrange(5) + rng.randrange(5), projectile.dimension)
    elif kind in POTIONS:
        _potion(state, projectile, target, cell)
    if projectile.alive:
        state.discard(projectile)


def owner(state, entity):
    """Projectile.getOwner: the entity of the ``Owner`` UUID, None without one."""
    found = entity.data.get("Owner")
    if not isinstance(found, IntArray) or len(found) != 4:
        return None
    return state.entities.by_uuid(tuple(int(v) for v in found))


def root(entity):
    """Entity.getRootVehicle."""
    while entity.vehicle is not None:
        entity = entity.vehicle
    return entity


def _thrown_hurt(state, projectile, target) -> None:
    """Snowball/ThrownEgg/ThrownEnderpearl.onHitEntity: ``thrown`` damage (3 from a snowball to a
    blaze, else 0), the owner responsible. An interaction entity is not hurt (Entity.hurt)."""
    if target.type == "minecraft:interaction":
        return
    if not living.is_living(target.type):
        raise Unmodelled(f"{projectile.type} hitting {target.type} (its hurt)")
    damage = 3.0 if projectile.type == "minecraft:snowball" and target.type == "minecraft:blaze" else 0.0
    combat.hurt(state, target, damage, DamageSource("minecraft:thrown", owner(state, projectile), projectile))


# ---------------------------------------------------------------------- egg
def _hatch(state, egg) -> None:
    rng = state.resources.random
    if rng.randrange(8) != 0:
        return
    count = 4 if rng.randrange(32) == 0 else 1
    blocks = state.blocks_in(egg.dimension)
    for _ in range(count):
        chick = state.entities.summon("minecraft:chicken", egg.pos, Compound(Age=Int(-24000)), yaw=float(egg.yaw),
                                      dimension=egg.dimension)
        if any(block_shapes.collides(blocks.get(c)) for c in ray.box_cells(chick.bounding_box) if not blocks.get(c).is_air):
            state.discard(chick)
            raise Unmodelled("an egg's chick inside a block (Entity.fudgePositionAfterSizeChange)")


# ---------------------------------------------------------------------- ender pearl
def _teleport_owner(state, pearl) -> None:
    thrower = owner(state, pearl)
    if thrower is None or not thrower.alive:
        return
    if thrower.dimension != pearl.dimension:
        raise Unmodelled("an ender pearl taking its owner to another dimension")
    if thrower.vehicle is not None:
        stop_riding(thrower)
    was = thrower.pos
    thrower.pos = pearl.pos
    thrower.data["FallDistance"] = Float(0.0)
    if thrower.is_player:
        if state.resources.random.random() < ENDERMITE_CHANCE and state.gamerules.get("doMobSpawning") != "false":
            state.entities.summon("minecraft:endermite", was, yaw=float(thrower.yaw), pitch=float(thrower.pitch),
                                  dimension=thrower.dimension)
        combat.hurt(state, thrower, PEARL_FALL_DAMAGE, DamageSource("minecraft:fall"))


# ---------------------------------------------------------------------- potions
def _potion(state, potion, target, cell) -> None:
    """ThrownPotion.onHit: water, else a lingering potion's cloud or a splash potion's effects."""
    item = potion.data.get("Item")
    stack = from_nbt(item) if isinstance(item, Compound) else None
    contents = stack.component("minecraft:potion_contents") if stack is not None else None
    if stack is not None and stack.component("minecraft:potion_duration_scale") is not None:
        raise Unmodelled("a thrown potion's potion_duration_scale")
    potion_id = str(contents.get("potion", "") if isinstance(contents, Compound) else contents or "")
    if potion_id in ("water", "minecraft:water"):
        _water(state, potion, cell)
        return
    effects = consumables.potion_effects(stack, state.version) if stack is not None else []
    if not effects:
        return
    if _lingering(potion, stack):
        _cloud(state, potion, contents)
    else:
        _splash(state, potion, target, effects)


def _lingering(potion, stack) -> bool:
    """1.21.5+: the entity's type; before, the item (ThrownPotion.isLingering)."""
    if potion.type != "minecraft:potion":
        return potion.type == "minecraft:lingering_potion"
    return stack.id == "minecraft:lingering_potion"


def _in_range(state, potion):
    """The living entities whose box meets the potion's inflated by 4, 2, 4 and whose position is
    within 4 of the potion's, with the squared distance."""
    x0, y0, z0, x1, y1, z1 = potion.bounding_box
    area = (x0 - 4.0, y0 - 2.0, z0 - 4.0, x1 + 4.0, y1 + 2.0, z1 + 4.0)
    for other in state.entities.entities:
        if not other.alive or other.dimension != potion.dimension or not living.is_living(other.type):
            continue
        box = other.bounding_box
        if not ray.boxes_meet(area, box):
            continue
        distance = sum((a - b) ** 2 for a, b in zip(other.pos, potion.pos))
        if distance < SPLASH_RANGE * SPLASH_RANGE:
            yield other, distance


def _splash(state, potion, target, effects) -> None:
    """ThrownPotion.applySplash."""
    source = owner(state, potion)
    given_by = source or potion  # Projectile.getEffectSource
    for entity, distance in list(_in_range(state, potion)):
        if not affected_by_potions(entity):
            continue
        scale = 1.0 if entity is target else 1.0 - math.sqrt(distance) / SPLASH_RANGE
        changed = False
        for effect_id, duration, amplifier in effects:
            if effect_id in living.INSTANT:
                instant_effect(state, potion, source, entity, effect_id, amplifier, scale)
                continue
            scaled = duration if duration == living.INFINITE else int(scale * duration + 0.5)
            if scaled != living.INFINITE and scaled <= 20:  # MobEffectInstance.endsWithin(20)
                continue
            changed |= living.give_effect(state, entity, effect_id, scaled, amplifier, True)
        if changed:
            advancements.effects_changed(state, entity, given_by)


def affected_by_potions(entity) -> bool:
    """LivingEntity.isAffectedByPotions: not dying; never an armor stand."""
    return entity.type != "minecraft:armor_stand" and living.health(entity) > 0


def instant_effect(state, direct, source, entity, effect_id: str, amplifier: int, scale: float) -> None:
    """HealOrHarmMobEffect.applyInstantenousEffect at ``scale`` from ``direct`` (a potion, a cloud)
    of ``source`` (its owner)."""
    if effect_id == "minecraft:saturation":
        raise Unmodelled("saturation from a potion or cloud (players' hunger)")
    heals = (effect_id == "minecraft:instant_health") != (entity.type in living.UNDEAD)
    amount = int(scale * float(_shifted(4 if heals else 6, amplifier)) + 0.5)
    if heals:
        living.heal(entity, float(amount))
    else:
        combat.hurt(state, entity, float(amount), DamageSource("minecraft:indirect_magic", source, direct))


def _shifted(base: int, amplifier: int) -> int:
    """``base << amplifier`` as a Java int."""
    value = (base << (amplifier & 31)) & 0xFFFFFFFF
    return value - (1 << 32) if value >= 1 << 31 else value


def _water(state, potion, cell) -> None:
    """ThrownPotion.applyWater: the water-sensitive are hurt by 1, the burning put out."""
    if cell is not None:
        _no_fire_near(state, potion, cell)
    source = owner(state, potion)
    for entity, _ in list(_in_range(state, potion)):
        if entity.type in ("minecraft:axolotl", "minecraft:enderman"):
            raise Unmodelled(f"a water bottle on {entity.type} (rehydrating it; an enderman teleports)")
        if entity.type in WATER_SENSITIVE:
            combat.hurt(state, entity, 1.0, DamageSource("minecraft:indirect_magic", source, potion))
        if entity.alive and _int(entity.data, "Fire", 0) > 0:
            entity.data["Fire"] = Short(0)  # Entity.extinguishFire


def _no_fire_near(state, potion, cell) -> None:
    """ThrownPotion.onHitBlock dowses fire, lit candles and campfires next to the hit: not
    modelled, so such a block around the block hit raises Unmodelled."""
    blocks = state.blocks_in(potion.dimension)
    x, y, z = cell
    for near in ((x + dx, y + dy, z + dz) for dx in (-1, 0, 1) for dy in (-1, 0, 1) for dz in (-1, 0, 1)):
        name = blocks.get(near).id
        if name.endswith("fire") or "candle" in name:
            raise Unmodelled(f"a water bottle putting out {name} (ThrownPotion.dowseFire)")


def _cloud(state, potion, contents) -> None:
    """ThrownPotion.makeAreaOfEffectCloud."""
    data = Compound(Radius=Float(_CLOUD["Radius"]), RadiusOnUse=Float(_CLOUD["RadiusOnUse"]),
                    WaitTime=Int(_CLOUD["WaitTime"]), Duration=Int(_CLOUD["Duration"]),
                    ReapplicationDelay=Int(_CLOUD["ReapplicationDelay"]),
                    RadiusPerTick=Float(float(-F32(_CLOUD["Radius"]) / F32(_CLOUD["Duration"]))))
    data["potion_contents"] = contents if isinstance(contents, Compound) else Compound(potion=String(str(contents)))
    thrower = owner(state, potion)
    if thrower is not None and living.is_living(thrower.type):
        data["Owner"] = IntArray(potion.data["Owner"])
    state.entities.summon("minecraft:area_effect_cloud", potion.pos, data, dimension=potion.dimension)


def _int(data, key: str, default: int) -> int:
    value = data.get(key)
    return int(numeric_value(value)) if is_numeric(value) else default
