"""A player's air under water: its ``Air`` as LivingEntity.baseTick counts it each tick.

- ``tick_air(state, hurt)``: every living player's air, ``hurt(state, entity, amount, source)``
  dealing its drowning (:func:`emulator.world.combat.hurt`); ``tick_entity(state, entity, hurt)``
  one entity's; ``tick_is_idle(state)``.
- ``eyes_in_water(blocks, entity) -> bool``: Entity.updateFluidOnEyes (isEyeInFluid(WATER)).

Each tick, for a player that is alive (LivingEntity.baseTick, after the fire of Entity.baseTick):
- its eyes are in water when the water in the cell at its eyes (x, eye y, z) reaches above them:
  the cell's y plus the water's height (:func:`emulator.world.fluids.height`: 8/9 for a source or
  a fall, 1 under more water), in floats as the game adds them, greater than the eyes' y;
- eyes in water, not in a bubble column: a player that can drown (not in the pack's
  ``#minecraft:can_breathe_under_water``, no water breathing, conduit power or breath of the
  nautilus, not creative or spectator: Abilities.invulnerable) loses 1 air; at -20 (from 26.1: at
  or below) the air becomes 0 and it takes 2 ``minecraft:drown`` damage. One that cannot drown
  keeps its air, or from 1.21.4 gets 4 back (from 26.1 not with breath of the nautilus alone);
- else (bubble column included) the air rises by 4 up to 300 (increaseAirSupply).
A player riding a vehicle that throws its riders off under water (dismountsUnderwater), an oxygen
bonus (respiration) that keeps the air by chance, and the releases whose rule is not known from
the sources here (air below -20 in 1.21.8 - 1.21.11) are reported as not modelled. Mobs' and armor stands' air (their types' own breathing: fish dry out,
the undead breathe water) is not modelled: one with its eyes in water, or with less than full
air, or a fish out of water, is reported. Only a pack's own ``#minecraft:can_breathe_under_water``
is read (the game's has no player).

Sources (decompiled): world/entity/LivingEntity.java (baseTick, decreaseAirSupply,
increaseAirSupply, canBreatheUnderwater; 1.21.3, 1.21.4, 1.21.7, 26.1.2: shouldTakeDrowningDamage),
world/entity/Entity.java (updateFluidOnEyes), world/effect/MobEffectUtil.java (hasWaterBreathing,
shouldEffectsRefillAirsupply), world/entity/player/Player.java (getMaxAirSupply 300 via Entity).
"""
from __future__ import annotations

import math

import numpy as np

from emulator.world import fluids, inventories, living
from emulator.world.items import enchantment_level
from emulator.world.errors import Unmodelled
from emulator.world.loot_context import DamageSource
from emulator.world.nbt_ops import is_numeric, numeric_value
from mcfunction_parser.nbt import Short

MAX_AIR = 300
REFILL = 4
DROWN_AT = -20
DROWN_DAMAGE = 2.0
WATER_BREATHING = ("minecraft:water_breathing", "minecraft:conduit_power", "minecraft:breath_of_the_nautilus")
NAUTILUS = "minecraft:breath_of_the_nautilus"
REFILL_IN_WATER = (1, 21, 4)  # a player that cannot drown gets air back under water (1.21.3: not)
AT_OR_BELOW = (26, 1, 0)  # shouldTakeDrowningDamage: air <= -20 (1.21.7: == -20)
BELOW_UNKNOWN = ((1, 21, 8), (26, 1, 0))
BREATHERS_TAG = "minecraft:can_breathe_under_water"
OXYGEN_BONUS_VERSION = (1, 21, 0)  # respiration gives the oxygen_bonus attribute (before: read off the helmet)
TAG_VERSION = (1, 20, 5)  # LivingEntity.canBreatheUnderwater reads the tag (before: each class's own)
# WaterAnimal.handleAirSupply and their like: out of water they lose air (not modelled)
AQUATIC = frozenset("minecraft:" + n for n in (
    "cod salmon tropical_fish pufferfish squid glow_squid dolphin axolotl tadpole nautilus").split())


def tick_is_idle(state) -> bool:
    return not any(_needs_tick(state, e) for e in state.entities.living_mobs())


def settled(entity) -> bool:
    """Full air and no fish: with no block at all around, nothing changes it (a caller's fast path)."""
    return entity.type not in AQUATIC and air(entity) >= MAX_AIR


def _needs_tick(state, entity) -> bool:
    """Whether the entity's air may change: less than full, or eyes in water (a fish: out of it)."""
    blocks = state.blocks_in(entity.dimension)
    if entity.type in AQUATIC:
        return not fluids.in_water(blocks, entity.bounding_box)
    if air(entity) < MAX_AIR:
        return True
    return blocks.derived("water", _holds_water) and eyes_in_water(blocks, entity)


def _holds_water(blocks) -> bool:
    """Whether any block of the level holds water (remade only when a block changes)."""
    return any(fluids.is_water(block) for block in blocks.states.values())


def tick_air(state, hurt) -> None:
    for entity in list(state.entities.living_mobs()):
        if entity.alive:
            tick_entity(state, entity, hurt)


def tick_entity(state, entity, hurt) -> None:
    """One living entity's air (the world step's body, for a caller looping over them already)."""
    if not _needs_tick(state, entity) or living.health(entity) <= 0:
        return
    try:
        if not entity.is_player:
            raise Unmodelled(f"the air of {entity.type} (its type's own breathing)")
        _breathe(state, entity, hurt)
    except Unmodelled as reason:
        state.unmodelled_once("air under water", reason)


def _breathe(state, player, hurt) -> None:
    blocks = state.blocks_in(player.dimension)
    supply = air(player)
    if eyes_in_water(blocks, player) and blocks.get(_eye_cell(player)).id != "minecraft:bubble_column":
        if player.vehicle is not None:
            raise Unmodelled("a rider under water (Entity.dismountsUnderwater)")
        if _can_drown(state, player):
            _lose_air(state, player, supply, hurt)
        elif supply < MAX_AIR and _refills_in_water(state, player):
            set_air(player, min(supply + REFILL, MAX_AIR))
    elif supply < MAX_AIR:
        set_air(player, min(supply + REFILL, MAX_AIR))


def _can_drown(state, player) -> bool:
    if player.gamemode in ("creative", "spectator"):
        return False
    if any(living.effect_amplifier(player, e) is not None for e in WATER_BREATHING):
        return False
    if state.version < TAG_VERSION:
        return True
    tag = state.resources.tags.get("entity_type", {}).get(BREATHERS_TAG)  # the game's own has no player
    return tag is None or player.type not in tag.members


def _refills_in_water(state, player) -> bool:
    version = state.version
    if version < REFILL_IN_WATER:
        return False
    if version >= AT_OR_BELOW and living.effect_amplifier(player, NAUTILUS) is not None:
        return any(living.effect_amplifier(player, e) is not None for e in WATER_BREATHING[:2])
    return True


def _keeps_air_by_chance(state, player) -> bool:
    """decreaseAirSupply's chance: the helmet's respiration (EnchantmentHelper.getRespiration before
    1.21; from 1.21 the oxygen_bonus attribute it gives, which the emulator does not add up from
    enchantments: looked at directly), or an oxygen_bonus from modifiers."""
    head = inventories.entity_slot(player, inventories.ARMOR_SLOTS["head"], state.version)
    if head is not None and enchantment_level(head.get(), "minecraft:respiration") > 0:
        return True
    return state.version >= OXYGEN_BONUS_VERSION and living.attribute_value(player, "oxygen_bonus") > 0.0


def _lose_air(state, player, supply: int, hurt) -> None:
    """decreaseAirSupply, then the drowning: 2 damage when the air reaches -20."""
    if _keeps_air_by_chance(state, player):
        raise Unmodelled("air kept by chance (an oxygen bonus: respiration)")
    supply -= 1
    version = state.version
    if supply < DROWN_AT and BELOW_UNKNOWN[0] <= version < BELOW_UNKNOWN[1]:
        raise Unmodelled("air below -20 in 1.21.8 - 1.21.11 (whether it drowns)")
    set_air(player, supply)
    if supply == DROWN_AT or (supply < DROWN_AT and version >= AT_OR_BELOW):
        set_air(player, 0)
        hurt(state, player, DROWN_DAMAGE, DamageSource("minecraft:drown"))


def eyes_in_water(blocks, entity) -> bool:
    """Entity.updateFluidOnEyes: the water's top in the eyes' cell, (float)y + height, above them."""
    cell = _eye_cell(entity)
    height = fluids.height(blocks, cell)
    return height is not None and float(np.float32(cell[1]) + np.float32(height)) > _eye_y(entity)


def _eye_y(entity) -> float:
    return entity.pos[1] + float(entity.eye_height)


def _eye_cell(entity) -> tuple[int, int, int]:
    x, _, z = entity.pos
    return math.floor(x), math.floor(_eye_y(entity)), math.floor(z)


def air(entity) -> int:
    value = entity.data.get("Air")
    if type(value) is Short:  # as the game saves it
        return int(value)
    return int(numeric_value(value)) if is_numeric(value) else MAX_AIR


def set_air(entity, value: int) -> None:
    entity.data["Air"] = Short(value)
