"""The one evaluator of loot item conditions (predicates) and the entity, location, block and item
predicates inside them, against a :class:`~emulator.world.loot_context.LootContext`. Read by
``execute if predicate``, ``@e[predicate=...]``, PackTest's ``assert predicate``, loot tables and
item modifiers (pools, entries, functions, ``filtered``) and advancement criteria.

API
- ``test(condition, ctx) -> bool``: one condition (a dict) or a list of them (all must hold).
- ``test_predicate(predicate_id, ctx) -> bool``: a loaded predicate file by id (``reference``'s
  semantics: an unknown id or a loop is false).
- ``entity_matches(predicate, ctx, entity)``, ``location_matches(predicate, ctx, pos)``,
  ``item_matches(predicate, ctx, stack)`` (an :class:`~emulator.world.items.ItemStack`),
  ``block_matches(predicate, ctx, pos)``: the sub-predicates.
- ``CONDITIONS``: condition type (without ``minecraft:``) -> evaluator ``(condition, ctx) -> bool``.
Anything a condition reads that the emulator does not model raises
:class:`~emulator.world.errors.Unmodelled` with the reason: never a silent true or false.

Sources (decompiled 1.21, net/minecraft/world/level/storage/loot/predicates/*, advancements/critereon/*):
- AllOfCondition / AnyOfCondition: Util.allOf (empty: true) / Util.anyOf (empty: false);
  InvertedLootItemCondition; ConditionReference (unknown id or a loop: false, logged).
- LootItemEntityPropertyCondition: the entity of the target and the origin; no predicate: true;
  EntityPredicate.matches: a missing entity fails; ``distance`` needs an origin.
- EntityPredicate (type, distance, location/stepping_on/movement_affected_by, effects, nbt, flags,
  equipment, type_specific, vehicle, passenger, targeted_entity, team, periodic_tick, slots,
  components: emulator.world.entity_components).
- EntityEquipmentPredicate.matches: only a LivingEntity matches; each given slot's ItemPredicate
  tests LivingEntity.getItemBySlot (an empty slot is the empty stack, which ``{}`` matches).
  SlotsPredicate: each slot range needs one slot (Entity.getSlot) whose stack matches.
- DistancePredicate: float differences, x/y/z on their absolute values, horizontal/absolute on
  squared lengths. LocationPredicate: position on the exact doubles, then the block at
  BlockPos.containing. LocationCheck: origin + offset. ExecuteCommand.checkCustomPredicate: the
  COMMAND parameter set (origin, this entity), the level's random.
- EntityHasScoreCondition, ValueCheckCondition (IntRange.test of getInt), TimeCheck (day time,
  ``period`` modulo, as an int), WeatherCheck, LootItemRandomChanceCondition (nextFloat() < chance),
  LootItemRandomChanceWithEnchantedBonusCondition, LootItemKilledByPlayerCondition (the
  attacking player parameter), ExplosionCondition (no radius: true), MatchTool (no tool: false),
  BonusLevelTableCondition (the tool's level picks the chance), LootItemBlockStatePropertyCondition,
  StatePropertiesPredicate (exact value or min/max on the property's value).
- ItemPredicate.test: items, count, exact components (DataComponentPredicate), sub-predicates;
  no special case for the empty stack.
"""
from __future__ import annotations

import math
from dataclasses import replace
from typing import Callable

import numpy as np

from emulator.world import (advancement_progress, biomes, campfires, entity_components, entity_flags,
                            entity_predicate_format, inventories, light, recipes, sight)
from emulator.world.blocks import knows_states
from emulator.world.entities import Entity, entity_nbt
from emulator.world.errors import Unmodelled
from emulator.world.item_predicates import codec_matches, predicate_tag
from emulator.world.items import COMPONENTS_VERSION, ItemStack, enchantment_level
from emulator.world.living import is_living
from emulator.world.loot_context import (LootContext, in_int_range, in_ints, in_range, integer, min_max, number,
                                         snbt_or_tag)
from emulator.world.nbt_ops import compare_nbt, is_numeric, numeric_value, tags_equal
from mcfunction_parser.items import SLOTS, sub_predicate_registered
from mcfunction_parser.nbt import Byte, Compound, Int, List
from mcfunction_parser.pack.tags import normalise_id

F32 = np.float32


def _kind(value: dict) -> str:
    kind = value.get("condition") or value.get("type") or ""
    return str(kind).removeprefix("minecraft:")


def _id(text: str) -> str:
    return text if ":" in text else "minecraft:" + text


# ---------------------------------------------------------------------- conditions
def test(condition, ctx: LootContext) -> bool:
    """One loot condition, or a list of them (all must hold, in order)."""
    if isinstance(condition, list):
        return all(test(c, ctx) for c in condition)
    handler = CONDITIONS.get(_kind(condition))
    if handler is None:
        raise Unmodelled(f"predicate condition '{condition.get('condition')}'")
    return handler(condition, ctx)


def test_predicate(predicate_id: str, ctx: LootContext) -> bool:
    """A loaded predicate by id; an unknown id or a loop is false (ConditionReference.test)."""
    predicate = ctx.resources.predicates.get(predicate_id)
    if predicate is None or not ctx.visit("predicate " + predicate_id):
        return False
    try:
        return test(predicate, ctx)
    finally:
        ctx.leave("predicate " + predicate_id)


def _entity_properties(c: dict, ctx: LootContext) -> bool:
    predicate = c.get("predicate")
    if predicate is None:
        return True
    return entity_matches(predicate, ctx, ctx.entity(c["entity"]))


def _entity_scores(c: dict, ctx: LootContext) -> bool:
    entity = ctx.entity(c["entity"])
    if entity is None:
        return False
    for objective, bounds in c.get("scores", {}).items():
        value = ctx.score(entity.score_holder, objective)
        if value is None or not in_int_range(bounds, value, ctx):
            return False
    return True


def _chance(chance, ctx: LootContext) -> bool:
    return ctx.random.random() < chance


def _enchanted_bonus(c: dict, ctx: LootContext) -> bool:
    """LootItemRandomChanceWithEnchantedBonusCondition (random_chance_with_looting before 1.21): the
    attacker's level of the enchantment picks the chance. An attacker whose equipment holds none of
    it has level 0 (the unenchanted chance); a level above 0 is not modelled (its slots and
    level-based chance are the enchantment's definition)."""
    enchantment = c.get("enchantment", "minecraft:looting")
    if ctx.attacker is not None and any(enchantment_level(s, enchantment) for s in equipment(ctx.attacker, ctx)):
        raise Unmodelled(f"an attacker's enchantment level ({c.get('condition')})")
    return _chance(float(c.get("unenchanted_chance", c.get("chance", 0.0))), ctx)


def _time_check(c: dict, ctx: LootContext) -> bool:
    """TimeCheck: the day time (the overworld's); from 26.1 the ticks of its ``clock``."""
    clocks, clock = ctx.state.clocks, c.get("clock")
    clock = normalise_id(clock) if isinstance(clock, str) else None
    time = clocks.ticks(clock) if clocks is not None and clock in clocks else ctx.state.daytime
    if c.get("period") is not None:
        time %= int(c["period"])
    return in_int_range(c["value"], _int32(time), ctx)


def _weather_check(c: dict, ctx: LootContext) -> bool:
    """WeatherCheck.test: the context's level's Level.isRaining / isThundering (emulator.world.weather)."""
    weather, dimension = ctx.state.weather, ctx.dimension
    raining, thundering = c.get("raining"), c.get("thundering")
    if raining is not None and bool(raining) != weather.is_raining(dimension):
        return False
    return thundering is None or bool(thundering) == weather.is_thundering(dimension)


def _location_check(c: dict, ctx: LootContext) -> bool:
    if ctx.origin is None:
        return False
    ox, oy, oz = ctx.origin
    pos = (ox + int(c.get("offsetX", 0)), oy + int(c.get("offsetY", 0)), oz + int(c.get("offsetZ", 0)))
    return location_matches(c.get("predicate", {}), ctx, pos)


def _block_state_property(c: dict, ctx: LootContext) -> bool:
    state = ctx.block_state
    if state is None or state.id != _id(c["block"]):
        return False
    return state_matches(c.get("properties"), state, ctx.version)


def _match_tool(c: dict, ctx: LootContext) -> bool:
    if ctx.tool is None:
        return False
    return "predicate" not in c or item_matches(c["predicate"], ctx, ctx.tool)


def _table_bonus(c: dict, ctx: LootContext) -> bool:
    """BonusLevelTableCondition: the tool's enchantment level (0 without a tool) picks the chance."""
    chances = c.get("chances", [])
    level = enchantment_level(ctx.tool, c.get("enchantment", ""))
    return bool(chances) and _chance(chances[min(level, len(chances) - 1)], ctx)


def _survives_explosion(c: dict, ctx: LootContext) -> bool:
    return ctx.explosion_radius is None or ctx.random.random() <= 1.0 / ctx.explosion_radius


def _damage_source(c: dict, ctx: LootContext) -> bool:
    """DamageSourceCondition: false without a damage source or an origin; no predicate: true; its
    entity predicates from the origin."""
    if ctx.damage_source is None or ctx.origin is None:
        return False
    return "predicate" not in c or damage_source_matches(
        c["predicate"], ctx.damage_source, ctx.resources, lambda predicate, entity: entity_matches(predicate, ctx, entity))


def damage_source_matches(wanted: dict | None, source, resources, entity_test) -> bool:
    """DamageSourcePredicate.matches: each of ``tags`` (``{id, expected}``: whether the damage type
    is in the tag), ``direct_entity`` and ``source_entity`` (``entity_test(predicate, entity)``; an
    absent entity fails), ``is_direct``. ``source``: a :class:`~emulator.world.loot_context.DamageSource`."""
    if wanted is None:
        return True
    unknown = set(wanted) - {"tags", "is_direct", "source_entity", "direct_entity"}
    if unknown:
        raise Unmodelled(f"damage source predicate field '{sorted(unknown)[0]}'")
    for tag in wanted.get("tags", ()):
        tag_id = _id(str(tag.get("id", "")).removeprefix("#"))
        if resources.in_tag("damage_type", tag_id, source.type) != bool(tag.get("expected")):
            return False
    for key, entity in (("direct_entity", source.direct), ("source_entity", source.attacker)):
        if key in wanted and (entity is None or not entity_test(wanted[key], entity)):
            return False
    return "is_direct" not in wanted or source.is_direct == bool(wanted["is_direct"])


def _killed_by_player(c: dict, ctx: LootContext) -> bool:
    """LootItemKilledByPlayerCondition: the attacking player parameter is present (``inverse``
    before 1.20.5)."""
    return (ctx.attacking_player is not None) != bool(c.get("inverse", False))


def _any_of(c: dict, ctx: LootContext) -> bool:
    return any(test(t, ctx) for t in c["terms"])


CONDITIONS: dict[str, Callable[[dict, LootContext], bool]] = {
    "inverted": lambda c, ctx: not test(c["term"], ctx),
    "all_of": lambda c, ctx: all(test(t, ctx) for t in c["terms"]),
    "any_of": _any_of,
    "alternative": _any_of,  # the name before 1.20
    "reference": lambda c, ctx: test_predicate(_id(c["name"]), ctx),
    "entity_properties": _entity_properties,
    "entity_scores": _entity_scores,
    "random_chance": lambda c, ctx: _chance(number(c["chance"], ctx), ctx),
    "random_chance_with_enchanted_bonus": _enchanted_bonus,
    "random_chance_with_looting": _enchanted_bonus,
    "value_check": lambda c, ctx: in_int_range(c["range"], integer(c["value"], ctx), ctx),
    "time_check": _time_check,
    "weather_check": _weather_check,
    "location_check": _location_check,
    "block_state_property": _block_state_property,
    "match_tool": _match_tool,
    "killed_by_player": _killed_by_player,
    "survives_explosion": _survives_explosion,
    "damage_source_properties": _damage_source,
    "table_bonus": _table_bonus,
}


def _range_sq(bounds, value_sq: float) -> bool:
    """MinMaxBounds.Doubles.matchesSqr: the bounds squared against a squared length."""
    lo, hi = min_max(bounds, ints=False)
    return (lo is None or value_sq >= lo * lo) and (hi is None or value_sq <= hi * hi)


def _int32(value: int) -> int:
    return ((value + 2**31) & 0xFFFFFFFF) - 2**31


# ---------------------------------------------------------------------- equipment and items
_EQUIPMENT_SLOTS = {"mainhand": inventories.MAINHAND, "offhand": inventories.OFFHAND, "body": inventories.BODY,
                    **inventories.ARMOR_SLOTS}


def _slot_stack(entity: Entity, slot: int, ctx: LootContext) -> ItemStack:
    """LivingEntity.getItemBySlot: the stack in the slot (the empty stack when none)."""
    access = inventories.entity_slot(entity, slot, ctx.version)
    return access.get() if access is not None else ItemStack("minecraft:air", 0)


def equipment(entity: Entity, ctx: LootContext) -> list[ItemStack]:
    """The stacks of a living entity's equipment slots (none for other entities)."""
    if not is_living(entity.type):
        return []
    return [_slot_stack(entity, slot, ctx) for slot in _EQUIPMENT_SLOTS.values()]


def _equipment(value: dict, ctx: LootContext, entity: Entity) -> bool:
    """EntityEquipmentPredicate.matches: a living entity whose given slots' stacks match."""
    if not is_living(entity.type):
        return False
    return all(item_matches(wanted, ctx, _slot_stack(entity, _EQUIPMENT_SLOTS[slot], ctx))
               for slot, wanted in value.items() if slot in _EQUIPMENT_SLOTS)


# SlotsPredicate.matchSlots over a SlotProvider: a slot the entity does not have is skipped; before,
# Entity.getSlot gave SlotAccess.NULL, read as the empty stack (mappings history of SlotsPredicate)
SKIPS_MISSING_SLOTS = (1, 21, 11)


def _slots(value: dict, ctx: LootContext, entity: Entity) -> bool:
    """SlotsPredicate.matches (1.20.5+): for each slot range (SlotRanges: ``container.*``,
    ``armor.head`` ...), some slot of it holds a stack the item predicate matches. A slot the
    entity does not have reads as the empty stack before 1.21.11 (so ``{}`` or ``minecraft:air``
    matches it there) and is skipped from it (:data:`SKIPS_MISSING_SLOTS`)."""
    skips = tuple(ctx.version) >= SKIPS_MISSING_SLOTS
    for name, wanted in value.items():
        entry = SLOTS.get(name)
        if entry is None:
            raise Unmodelled(f"slot range '{name}'")
        slots = [s for s in entry[0] if not skips or inventories.entity_slot(entity, s, ctx.version) is not None]
        if not any(item_matches(wanted, ctx, _slot_stack(entity, slot, ctx)) for slot in slots):
            return False
    return True


def item_matches(predicate: dict, ctx: LootContext, stack: ItemStack) -> bool:
    """ItemPredicate.test: from 1.20.5 the codec's fields (``items``, ``count``, ``components``,
    ``predicates``: :func:`emulator.world.item_predicates.codec_matches`); before, ``items``
    (``item``/``tag`` before 1.17), ``count``, ``nbt`` (a partial match of the stack's tag) and
    :func:`_old_item_fields`."""
    if tuple(ctx.version) >= COMPONENTS_VERSION:
        return codec_matches(predicate_tag(predicate), stack, ctx.resources, ctx.version)
    wanted = predicate.get("items", predicate.get("item"))
    if "tag" in predicate:
        wanted = "#" + predicate["tag"]
    if wanted is not None and not _holder_set(wanted, "item", stack.id, ctx):
        return False
    if "count" in predicate and not in_ints(predicate["count"], stack.count):
        return False
    if "nbt" in predicate and not compare_nbt(snbt_or_tag(predicate["nbt"]), stack.tag):
        return False
    return _old_item_fields(predicate, stack)


def _old_item_fields(predicate: dict, stack: ItemStack) -> bool:
    """ItemPredicate.matches before 1.20.5: ``durability`` (a damageable item's max damage less its
    ``Damage``), ``enchantments`` / ``stored_enchantments`` (each EnchantmentPredicate contained in
    the ``Enchantments`` / ``StoredEnchantments`` of the tag), ``potion`` (the tag's ``Potion``,
    ``minecraft:empty`` when none)."""
    tag = stack.tag or Compound()
    if "durability" in predicate:
        max_damage = stack.component("minecraft:max_damage")
        if max_damage is None or _true(tag.get("Unbreakable")) or not in_ints(
                predicate["durability"], int(max_damage) - _int(tag.get("Damage"))):
            return False
    for key, saved in (("enchantments", "Enchantments"), ("stored_enchantments", "StoredEnchantments")):
        levels = _old_enchantments(tag.get(saved))
        if not all(_old_enchantment_in(wanted, levels) for wanted in predicate.get(key) or ()):
            return False
    return "potion" not in predicate or _id(predicate["potion"]) == _id(str(tag.get("Potion") or "empty"))


def _true(value) -> bool:
    return _int(value) != 0


def _int(value) -> int:
    """CompoundTag.getInt: a number's int value, 0 for anything else."""
    return int(numeric_value(value)) if is_numeric(value) else 0


def _old_enchantments(entries) -> dict[str, int]:
    """EnchantmentHelper.deserializeEnchantments: ``{id, lvl}`` entries, the level clamped to 0 - 255."""
    levels = {}
    for entry in entries if isinstance(entries, List) else ():
        if isinstance(entry, Compound) and "id" in entry:
            levels[_id(str(entry["id"]))] = min(max(_int(entry.get("lvl")), 0), 255)
    return levels


def _old_enchantment_in(wanted: dict, levels: dict[str, int]) -> bool:
    """EnchantmentPredicate.containedIn before 1.20.5: the ``enchantment`` present within
    ``levels``; without one, some enchantment within ``levels``; with neither, true."""
    bounds = wanted.get("levels")
    if "enchantment" in wanted:
        level = levels.get(_id(wanted["enchantment"]))
        return level is not None and (bounds is None or in_ints(bounds, level))
    return bounds is None or any(in_ints(bounds, level) for level in levels.values())
# ---------------------------------------------------------------------- entities
def entity_matches(predicate, ctx: LootContext, entity: Entity | None) -> bool:
    """EntityPredicate.matches(level, ctx.origin, entity); a list is a ContextAwarePredicate of
    loot conditions run with the entity as ``this`` at its position."""
    if isinstance(predicate, list):
        return entity is not None and test(predicate, ctx.for_entity(entity))
    if entity is None:
        return False
    for key, value in entity_predicate_format.classic(predicate, ctx.state.version).items():
        check = _ENTITY_FIELDS.get(key)
        if check is None:
            if key in _ENTITY_UNMODELLED:
                raise Unmodelled(f"entity predicate field '{key}'")
            continue  # the codec ignores unknown fields
        if not check(value, ctx, entity):
            return False
    return True


def _type_matches(value, ctx: LootContext, entity: Entity) -> bool:
    return _holder_set(value, "entity_type", entity.type, ctx)


def _holder_set(value, registry: str, member: str, ctx: LootContext) -> bool:
    """A HolderSet: an id, ``#tag`` or a list of ids."""
    if isinstance(value, list):
        return member in {_id(v) for v in value}
    if isinstance(value, str) and value.startswith("#"):
        return ctx.state.resources.in_tag(registry, _id(value[1:]), member)
    return member == _id(str(value))


def _distance(value: dict, ctx: LootContext, entity: Entity) -> bool:
    return ctx.origin is not None and distance_matches(value, ctx.origin, entity.pos)


def distance_matches(value: dict, origin, pos) -> bool:
    """DistancePredicate.matches: the float differences per axis, horizontal and absolute."""
    dx, dy, dz = (float(F32(a - b)) for a, b in zip(origin, pos))
    for axis, d in (("x", dx), ("y", dy), ("z", dz)):
        if axis in value and not in_range(value[axis], abs(d)):
            return False
    if "horizontal" in value and not _range_sq(value["horizontal"], dx * dx + dz * dz):
        return False
    return "absolute" not in value or _range_sq(value["absolute"], dx * dx + dy * dy + dz * dz)


def _nbt(value, ctx: LootContext, entity: Entity) -> bool:
    """NbtPredicate: the entity's saved NBT (a player's with its SelectedItem), a partial match."""
    return compare_nbt(snbt_or_tag(value), entity_nbt(entity))


def _number_field(entity: Entity, key: str) -> float:
    tag = entity.data.get(key)
    return numeric_value(tag) if is_numeric(tag) else 0.0


def _effects(value: dict, ctx: LootContext, entity: Entity) -> bool:
    """MobEffectsPredicate over the entity's ``active_effects`` (as ``effect give`` saves them)."""
    active = {}
    for effect in entity.data.get("active_effects", []):
        if isinstance(effect, dict) and "id" in effect:
            active[_id(str(effect["id"]))] = effect
    for effect_id, wanted in value.items():
        found = active.get(_id(effect_id))
        if found is None:
            return False
        for key, field_name in (("amplifier", "amplifier"), ("duration", "duration")):
            if key in wanted and not in_ints(wanted[key], int(numeric_value(found.get(field_name, Int(0))))):
                return False
        for key, field_name in (("ambient", "ambient"), ("visible", "show_particles")):
            if key in wanted and bool(numeric_value(found.get(field_name, Byte(0)))) != bool(wanted[key]):
                return False
    return True


def _location_field(key: str):
    """``location`` (the entity's exact position), ``stepping_on`` and ``movement_affected_by``
    (EntityPredicate.matches: Vec3.atCenterOf the block getOnPos finds 0.2 below the feet, and
    getBlockPosBelowThatAffectsMyMovement 0.500001 below; the supporting block an entity on a
    block's edge stands on is not modelled: the block under its position is taken)."""
    drop = {"stepping_on": 0.2, "movement_affected_by": 0.500001}.get(key)

    def check(value: dict, ctx: LootContext, entity: Entity) -> bool:
        x, y, z = entity.pos
        if drop is None:
            return location_matches(value, ctx, (x, y, z))
        if key == "stepping_on" and tuple(ctx.version) >= STEPPING_NEEDS_GROUND and not _number_field(entity, "OnGround"):
            return False
        return location_matches(value, ctx, tuple(math.floor(v) + 0.5 for v in (x, y - drop, z)))
    return check


# stepping_on holds only for an entity on the ground (entity.onGround()): in the 1.21.11 and 26.1
# sources, not in 1.21's; the release between that added it is unconfirmed
STEPPING_NEEDS_GROUND = (1, 21, 11)


def _targeted_entity(value, ctx: LootContext, entity: Entity) -> bool:
    """EntityPredicate.targetedEntity: a Mob's getTarget(), null for any other entity (which fails,
    as EntityPredicate.matches does for a missing entity). A mob with ``NoAI`` never acquires one
    (its goals do not run); another mob's target comes from its AI, which is not modelled."""
    if not is_living(entity.type) or entity.is_player or entity.type == "minecraft:armor_stand":
        return False
    if _number_field(entity, "NoAI"):
        return False
    raise Unmodelled(f"entity predicate field 'targeted_entity' (a {entity.type}'s target comes from its AI, "
                     "which is not modelled)")


def _entity_components(value, ctx: LootContext, entity: Entity) -> bool:
    """DataComponentMatchers' exact ``components`` (1.21.5+; the codec ignores the field before);
    ``custom_data`` equal to the entity's (:func:`entity_custom_data`)."""
    if tuple(ctx.state.version) < ENTITY_COMPONENTS_VERSION or not isinstance(value, dict):
        return True
    others = {k: v for k, v in value.items() if _id(k) != "minecraft:custom_data"}
    for key in value.keys() - others.keys():
        if not tags_equal(snbt_or_tag(value[key]), entity_custom_data(entity, ctx)):
            return False
    return entity_components.components_match(others, entity)


# Entity.get(CUSTOM_DATA) is the entity's ``data`` (saved when not empty): in the 26.1 source, not
# in 1.21.4's; the release between that added it is unconfirmed
ENTITY_CUSTOM_DATA = (26, 1, 0)


def entity_custom_data(entity: Entity, ctx: LootContext) -> Compound:
    """The entity's custom_data component: its ``data`` compound, empty when it has none."""
    if tuple(ctx.state.version) < ENTITY_CUSTOM_DATA:
        raise Unmodelled("an entity's custom_data component (its 'data': in the 26.1 source, the release that "
                         "added it is unconfirmed)")
    data = entity.data.get("data")
    return data if isinstance(data, Compound) else Compound()


def _entity_sub_predicates(value, ctx: LootContext, entity: Entity) -> bool:
    """DataComponentMatchers' ``predicates`` (1.21.5+; ignored before): each sub-predicate reads one
    component through Entity.get and fails when the entity has none
    (SingleComponentItemPredicate.matches). Of the registered ones only ``villager/variant`` reads a
    component an entity exposes (a villager's type, :mod:`emulator.world.entity_components`); the
    others read item components no entity has. ``custom_data`` (NbtPredicate over the entity's
    custom data, empty when none: :func:`entity_custom_data`) matches partly."""
    if tuple(ctx.state.version) < ENTITY_COMPONENTS_VERSION or not isinstance(value, dict):
        return True
    for name, wanted in value.items():
        full = _id(name)
        if full == "minecraft:custom_data":
            if not compare_nbt(snbt_or_tag(wanted), entity_custom_data(entity, ctx)):
                return False
        elif full == "minecraft:villager/variant":
            found = entity_components.component(entity, full)
            if found is None or not _holder_set(wanted, "villager_type", found, ctx):
                return False
        elif sub_predicate_registered(full, ctx.state.version):
            return False  # an item's component: Entity.get gives none
        else:
            raise Unmodelled(f"entity sub-predicate '{name}'")
    return True


def _periodic_tick(value, ctx: LootContext, entity: Entity) -> bool:
    """EntityPredicate.matches: ``entity.tickCount % periodic_tick == 0``. tickCount grows by one in
    each tick's entity phase (ServerLevel.tickNonPassenger / tickPassenger), after that tick's
    functions: here every entity ticks every tick, as where a player is near, so an entity's count
    is the ticks the server finished since it came into the world (a new entity, or a player that
    joined, starts at 0)."""
    return entity.tick_count(ctx.state.tick) % int(value) == 0


def _team(value, ctx: LootContext, entity: Entity) -> bool:
    return entity.team is not None and entity.team == value


def _vehicle(value, ctx: LootContext, entity: Entity) -> bool:
    return entity_matches(value, ctx, entity.vehicle)


def _passenger(value, ctx: LootContext, entity: Entity) -> bool:
    return any(entity_matches(value, ctx, p) for p in entity.passengers)


def _type_specific(value: dict, ctx: LootContext, entity: Entity) -> bool:
    kind = _kind(value)
    if kind == "player":
        return _player(value, ctx, entity)
    if kind == "slime":  # SlimePredicate: a slime or magma cube whose Size + 1 is in range
        if entity.type not in ("minecraft:slime", "minecraft:magma_cube"):
            return False
        return in_ints(value.get("size", {}), int(_number_field(entity, "Size")) + 1)
    raise Unmodelled(f"type_specific predicate '{value.get('type')}'")


def _player(value: dict, ctx: LootContext, entity: Entity) -> bool:
    """PlayerPredicate: the entity must be a player; gamemode, level, advancements, recipes (its
    recipe book) and looking_at (:func:`emulator.world.sight.looked_at`) are modelled."""
    if not entity.is_player:
        return False
    for key, wanted in value.items():
        if key == "type":
            continue
        if key == "gamemode":
            modes = wanted if isinstance(wanted, list) else [wanted]
            if entity.gamemode not in modes:
                return False
        elif key == "level":
            if not in_ints(wanted, entity.level):
                return False
        elif key == "advancements":
            if not advancement_progress.matches(ctx.state, entity, wanted):
                return False
        elif key == "recipes":  # RecipeBook.contains of each id, equal to the wanted boolean
            book = recipes.known(entity)
            if any((_id(r) in book) != bool(expected) for r, expected in wanted.items()):
                return False
        elif key == "looking_at":  # EntityPredicate.matches(player, entity): from the player's position
            seen = sight.looked_at(ctx.state, entity)
            if not entity_matches(wanted, replace(ctx, origin=entity.pos), seen):
                return False
        else:
            raise Unmodelled(f"player predicate field '{key}'")
    return True


_ENTITY_FIELDS = {
    "type": _type_matches,
    "entity_tags": lambda value, ctx, entity: entity_predicate_format.tags_match(value, entity),
    "distance": _distance,
    "nbt": _nbt,
    "flags": lambda value, ctx, entity: entity_flags.flags_match(value, ctx.state, entity),
    "effects": _effects,
    "location": _location_field("location"),
    "stepping_on": _location_field("stepping_on"),
    "movement_affected_by": _location_field("movement_affected_by"),
    "team": _team,
    "targeted_entity": _targeted_entity,
    "vehicle": _vehicle,
    "passenger": _passenger,
    "type_specific": _type_specific,
    "equipment": _equipment,
    "slots": _slots,
    "player": lambda v, ctx, e: _player(v, ctx, e),  # before 1.19: a top-level player predicate
    "components": lambda v, ctx, e: _entity_components(v, ctx, e),
    "predicates": _entity_sub_predicates,
    "periodic_tick": _periodic_tick,
}
_ENTITY_UNMODELLED = {"movement", "fishing_hook",
                      "lightning_bolt", "catType"}
ENTITY_COMPONENTS_VERSION = (1, 21, 5)  # EntityPredicate's DataComponentMatchers


# ---------------------------------------------------------------------- locations and blocks
def location_matches(predicate: dict, ctx: LootContext, pos) -> bool:
    """LocationPredicate.matches at exact ``pos``: position ranges, dimension, then at
    BlockPos.containing(pos) the biome (``biomes``, a HolderSet, from 1.20.5; ``biome``, one id,
    before), structures, ``smokey``, block and fluid. A field the world cannot answer is reported
    after the fields it can test held (when one of them fails the predicate is false whatever it says)."""
    position = predicate.get("position", {})
    for axis, value in zip("xyz", pos):
        if axis in position and not in_range(position[axis], value):
            return False
    if "dimension" in predicate and _id(predicate["dimension"]) != ctx.dimension:
        return False
    block_pos = tuple(math.floor(v) for v in pos)
    unknown = None
    for check in (_biome_check, _structure_check, _smokey_check, _light_check, _sky_check):
        try:
            if not check(predicate, ctx, block_pos):
                return False
        except Unmodelled as reason:
            unknown = unknown or reason
    if "block" in predicate and not block_matches(predicate["block"], ctx, block_pos):
        return False
    if "fluid" in predicate and not _fluid_matches(predicate["fluid"], ctx, block_pos):
        return False
    if unknown is not None:
        raise unknown
    return True


def _biome_check(predicate: dict, ctx: LootContext, pos) -> bool:
    wanted = predicate.get("biomes" if tuple(ctx.version) >= COMPONENTS_VERSION else "biome")
    return wanted is None or _holder_set(wanted, "worldgen/biome", biomes.biome_at(ctx.state, ctx.dimension, pos), ctx)


def _structure_check(predicate: dict, ctx: LootContext, pos) -> bool:
    """``structures`` (``structure``, one id, before 1.20.5; ``feature`` before 1.19): a structure
    with a piece at the block. The test server's world is made without them (GameTestServer's
    WorldOptions: generateStructures false), so there no structure is anywhere; another world's
    structures would come from terrain the emulator does not generate."""
    if not any(key in predicate for key in ("structures", "structure", "feature")):
        return True
    if ctx.state.structures_generated is False:
        return False
    raise Unmodelled("location predicate field 'structures' (the emulator generates no terrain, so it does not "
                     "know the structures of this world: only the test server's world is known to have none)")


def _smokey_check(predicate: dict, ctx: LootContext, pos) -> bool:
    """``smokey``: equal to CampfireBlock.isSmokeyPos at the block (:mod:`emulator.world.campfires`)."""
    return "smokey" not in predicate or bool(predicate["smokey"]) == campfires.is_smokey_pos(
        ctx.state.blocks_in(ctx.dimension), pos, ctx.state.resources)


def _light_check(predicate: dict, ctx: LootContext, pos) -> bool:
    """``light``: LightPredicate, its ``light`` range over Level.getMaxLocalRawBrightness
    (:func:`emulator.world.light.brightness`)."""
    if "light" not in predicate:
        return True
    bounds = predicate["light"].get("light", {}) if isinstance(predicate["light"], dict) else {}
    return _about("light", lambda: in_ints(bounds, light.brightness(ctx.state, ctx.dimension, pos)))


def _sky_check(predicate: dict, ctx: LootContext, pos) -> bool:
    """``can_see_sky``: equal to Level.canSeeSky at the block (:func:`emulator.world.light.can_see_sky`)."""
    return "can_see_sky" not in predicate or _about("can_see_sky", lambda: bool(predicate["can_see_sky"]) == (
        light.can_see_sky(ctx.state, ctx.dimension, pos)))


def _about(field: str, check: Callable[[], bool]) -> bool:
    """``check()``, its not-modelled reason naming the location predicate field."""
    try:
        return check()
    except Unmodelled as reason:
        raise Unmodelled(f"location predicate field '{field}' ({reason.reason})") from None



def block_matches(predicate: dict, ctx: LootContext, pos) -> bool:
    """BlockPredicate: ``blocks`` (id, list or #tag; ``block``/``tag`` before 1.20.5), ``state``,
    ``nbt`` (the block entity's, partial)."""
    blocks = ctx.state.blocks_in(ctx.dimension)
    state = blocks.get(pos)
    wanted = predicate.get("blocks", predicate.get("block"))
    if "tag" in predicate:
        wanted = "#" + predicate["tag"]
    if wanted is not None and not _holder_set(wanted, "block", state.id, ctx):
        return False
    if "state" in predicate and not state_matches(predicate["state"], state, ctx.version):
        return False
    if "nbt" in predicate:
        return compare_nbt(snbt_or_tag(predicate["nbt"]), blocks.block_nbt(pos, quiet=True))
    return True


def state_matches(wanted: dict | None, state, version) -> bool:
    """StatePropertiesPredicate.matches for a block state of ``version``."""
    return _state_matches(wanted, dict(state.properties), state.id, knows_states(state.id, version))


def _state_matches(wanted: dict | None, properties: dict[str, str], block_id: str, complete: bool) -> bool:
    """StatePropertiesPredicate: each property equal to a value, or within ``{min, max}``; a property
    the state does not have fails (PropertyMatcher.match: no such property). ``complete``: the
    properties are the state's whole set, else a property not listed is one the emulator does not know."""
    for name, value in (wanted or {}).items():
        if name not in properties:
            if complete:
                return False
            raise Unmodelled(f"the '{name}' state of {block_id} (not in the registries of this release)")
        actual = properties[name]
        if isinstance(value, dict):
            if not _property_in_range(actual, value):
                return False
        elif actual != _property_text(value):
            return False
    return True


def _property_text(value) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    return str(value)


def _property_in_range(actual: str, bounds: dict) -> bool:
    lo, hi = bounds.get("min"), bounds.get("max")
    try:
        number_value = int(actual)
        return (lo is None or number_value >= int(lo)) and (hi is None or number_value <= int(hi))
    except (TypeError, ValueError):
        return (lo is None or actual >= _property_text(lo)) and (hi is None or actual <= _property_text(hi))


def _fluid_matches(predicate: dict, ctx: LootContext, pos) -> bool:
    """FluidPredicate on the block's fluid: water and lava blocks (level 0: the source, else
    flowing), a waterlogged block's water; every other block holds none (minecraft:empty)."""
    state = ctx.state.blocks_in(ctx.dimension).get(pos)
    properties = dict(state.properties)
    fluid, fluid_props = "minecraft:empty", {}
    if state.id in ("minecraft:water", "minecraft:lava"):
        level = int(properties.get("level", "0"))
        name = state.id.split(":")[1]
        fluid = state.id if level == 0 else f"minecraft:flowing_{name}"
        fluid_props = {"falling": "true" if level >= 8 else "false"} | ({"level": str(8 - level % 8)} if level else {})
    elif properties.get("waterlogged") == "true":
        fluid = "minecraft:water"
    wanted = predicate.get("fluids", predicate.get("fluid"))
    if "tag" in predicate:
        wanted = "#" + predicate["tag"]
    if wanted is not None and not _holder_set(wanted, "fluid", fluid, ctx):
        return False
    return "state" not in predicate or _state_matches(predicate["state"], fluid_props, fluid, True)


