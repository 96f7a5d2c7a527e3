"""Entities on fire: their ``Fire`` ticks (Entity.remainingFireTicks) as the server's Entity.baseTick
counts them.

- ``tick_burning(state, hurt)``: each burning entity's fire tick, ``hurt(state, entity, amount,
  source)`` dealing its fire damage (:func:`emulator.world.combat.hurt`); ``tick_is_idle(state)``:
  none burns.
- ``is_on_fire(entity)``: Entity.isOnFire on the server: ``Fire`` > 0 and not fire immune
  (``HasVisualFire`` only shows on clients).
- ``ignite_for_ticks(entity, ticks)``: Entity.igniteForTicks: ``Fire`` raised to ``ticks``.

Each tick (Entity.baseTick) an entity in water (:func:`emulator.world.fluids.in_water`) is put out
first (updateInWaterStateAndDoWaterCurrentPushing: clearFire, ``Fire`` 0); then one
with ``Fire`` > 0 burns: a fire-immune type (EntityType.fireImmune: blaze, ghast, magma cube,
strider, wither ...) loses 4 ticks and is cleared to 0 below it; any other is hurt by 1 as
``on_fire`` damage when ``Fire`` is a multiple of 20 (a living one: HurtTime, death, the hurt's
triggers; ``fire_resistance`` stops it: LivingEntity.hurt, DamageTypeTags.IS_FIRE) and loses one.
A projectile, marker-like entity or other non-living one only counts down (Entity.hurt does
nothing).

Not modelled (Unmodelled, the test is inconclusive): the fire hurt of items, experience orbs,
armor stands, boats, minecarts and hanging entities (their own hurt), being in lava (lavaHurt, and
no fire hurt there), and catching fire from fire blocks or lava (reported by
:mod:`emulator.world.block_contact`); rain or a bubble column putting a moving entity out
(Entity.move: entities do not move here) and powder snow.

Sources (decompiled 1.21): world/entity/Entity.java (baseTick, igniteForTicks, igniteForSeconds,
clearFire, isOnFire, updateInWaterStateAndDoWaterCurrentPushing, updateFluidHeightAndDoFluidPushing),
world/entity/EntityType.java (fireImmune), world/entity/LivingEntity.java (hurt: fire resistance).
"""
from __future__ import annotations

from emulator.world import fluids, living, ray
from emulator.world.errors import Unmodelled
from emulator.world.loot_context import DamageSource
from emulator.world.nbt_ops import is_numeric, numeric_value
from mcfunction_parser.nbt import Short

FIRE_IMMUNE = frozenset("minecraft:" + n for n in (
    "area_effect_cloud blaze end_crystal ender_dragon ghast magma_cube shulker strider tnt vex warden wither "
    "wither_skeleton zoglin zombified_piglin fishing_bobber").split())
# entities whose tick never reaches Entity.baseTick (Marker/Interaction.tick are empty, Display.tick
# does not call it)
_NO_BASE_TICK = frozenset("minecraft:" + n for n in (
    "marker interaction block_display item_display text_display").split())
# not living, with a hurt of their own
_OWN_HURT = ("minecraft:item", "minecraft:experience_orb", "minecraft:armor_stand", "minecraft:item_frame",
             "minecraft:glow_item_frame", "minecraft:painting", "minecraft:leash_knot")
_OWN_HURT_SUFFIXES = ("boat", "_raft", "minecart")
HURT_EVERY = 20
IMMUNE_STEP = 4


def fire(entity) -> int:
    value = entity.data.get("Fire")
    return int(numeric_value(value)) if is_numeric(value) else 0


def is_on_fire(entity) -> bool:
    """Entity.isOnFire on the server."""
    return fire(entity) > 0 and entity.type not in FIRE_IMMUNE


def ignite_for_ticks(entity, ticks: int) -> None:
    """Entity.igniteForTicks."""
    if fire(entity) < ticks:
        entity.data["Fire"] = Short(ticks)


def _base_ticks(type_id: str) -> bool:
    return type_id not in _NO_BASE_TICK


def _burning(state):
    ticking = state.entities.picked("base_tick", _base_ticks)
    # a cheap first look (most entities have no Fire above 0), then fire() reads it as the game does
    return [e for e in ticking if is_numeric(fire_tag := e.data.get("Fire")) and fire_tag > 0 and fire(e) > 0
            and e.alive]


def tick_is_idle(state) -> bool:
    return not _burning(state)


def tick_burning(state, hurt) -> None:
    """Entity.baseTick's fire for every burning entity, in the entities' order."""
    for entity in _burning(state):
        if not entity.alive or (entity.is_player and entity.gamemode == "spectator"):
            continue
        if fluids.in_water(state.blocks_in(entity.dimension), entity.bounding_box):
            entity.data["Fire"] = Short(0)  # clearFire
            continue
        ticks = fire(entity)
        if _in(state, entity, "lava"):
            raise Unmodelled(f"{entity.type} burning in lava (Entity.lavaHurt)")
        if entity.type in FIRE_IMMUNE:
            ticks -= IMMUNE_STEP
            entity.data["Fire"] = Short(0 if ticks < 0 else ticks)
            continue
        if ticks % HURT_EVERY == 0:
            _fire_hurt(state, entity, hurt)
        entity.data["Fire"] = Short(ticks - 1)


def _fire_hurt(state, entity, hurt) -> None:
    """Entity.hurt(onFire, 1): only a living entity's does anything here."""
    if entity.type in _OWN_HURT or entity.type.endswith(_OWN_HURT_SUFFIXES):
        raise Unmodelled(f"a burning {entity.type}'s hurt")
    if not living.is_living(entity.type):
        return
    if living.effect_amplifier(entity, "minecraft:fire_resistance") is not None:
        return  # LivingEntity.hurt: IS_FIRE with fire resistance
    hurt(state, entity, 1.0, DamageSource("minecraft:on_fire"))


def _cells_of(entity):
    x0, y0, z0, x1, y1, z1 = entity.bounding_box
    return (x0 + 0.001, y0 + 0.001, z0 + 0.001, x1 - 0.001, y1 - 0.001, z1 - 0.001)


def _in(state, entity, fluid: str) -> bool:
    """Whether the box (less 0.001) meets a block of ``fluid`` (its whole cell: lava is only
    reported)."""
    blocks = state.blocks_in(entity.dimension)
    return any(blocks.get(c).id == "minecraft:" + fluid for c in ray.box_cells(_cells_of(entity)))
