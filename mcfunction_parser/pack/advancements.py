"""Advancement JSON as the game loads it (``data/<ns>/advancement/<path>.json``, ``advancements/``
before 1.21): the structural checks that make the game refuse a file, and the criteria triggers.

Advancement.CODEC (decompiled 1.21): ``criteria`` is a required map of name -> criterion, each with
a ``trigger`` known to CriteriaTriggers and optional ``conditions``; a trigger's ``player`` (and
the other entity fields) is a ContextAwarePredicate: an entity predicate object, or (1.20+) a list
of loot conditions. ``requirements`` is a list of lists of criterion names (default: every
criterion its own group, so all are needed) and every name in it must be a criterion.
"""
from __future__ import annotations

from typing import Any

from mcfunction_parser.diagnostics import Diagnostic
from mcfunction_parser.pack import conditions, predicate_ids
from mcfunction_parser.pack.text import JsonDocument

# CriteriaTriggers (1.21, with the 1.21.x additions); names without the namespace.
TRIGGERS = frozenset("""
impossible player_killed_entity entity_killed_player enter_block inventory_changed recipe_unlocked
player_hurt_entity entity_hurt_player enchanted_item filled_bucket brewed_potion construct_beacon
used_ender_eye summoned_entity bred_animals location slept_in_bed cured_zombie_villager villager_trade
item_durability_changed levitation changed_dimension tick tame_animal placed_block consume_item
effects_changed used_totem nether_travel fishing_rod_hooked channeled_lightning shot_crossbow
killed_by_crossbow killed_by_arrow hero_of_the_village voluntary_exile slide_down_block
bee_nest_destroyed target_hit item_used_on_block default_block_use any_block_use
player_generates_container_loot thrown_item_picked_up_by_entity thrown_item_picked_up_by_player
player_interacted_with_entity player_sheared_equipment started_riding lightning_strike using_item
fall_from_height ride_entity_in_lava kill_mob_near_sculk_catalyst allay_drop_item_on_block
avoid_vibration recipe_crafted crafter_recipe_crafted fall_after_explosion safely_harvest_honey
""".split())


# the trigger condition fields that are ContextAwarePredicates (an entity predicate, or a list of
# loot conditions); other list fields (inventory_changed's ``items`` ...) are not conditions
CONTEXT_FIELDS = frozenset("player entity child parent partner villager zombie projectile shooter victim "
                           "source bystander lightning location".split())


def criteria(advancement: dict) -> dict[str, dict]:
    return advancement.get("criteria", {})


def requirements(advancement: dict) -> list[list[str]]:
    """AdvancementRequirements: the groups (each needs one of its criteria); by default every
    criterion is its own group (AdvancementRequirements.allOf)."""
    given = advancement.get("requirements")
    if isinstance(given, list) and given:
        return [list(group) for group in given]
    return [[name] for name in criteria(advancement)]


def problem(value: Any, version) -> tuple[str, str] | None:
    """Why the game refuses the advancement: (message, JSON string to point at), or None."""
    if not isinstance(value, dict):
        return "an advancement must be a JSON object", ""
    found = value.get("criteria")
    if not isinstance(found, dict) or not found:
        return 'an advancement needs "criteria": an object of named criteria', "criteria"
    for name, criterion in found.items():
        if not isinstance(criterion, dict) or not isinstance(criterion.get("trigger"), str):
            return f'criterion "{name}" needs "trigger"', name
        trigger = criterion["trigger"]
        if trigger.removeprefix("minecraft:") not in TRIGGERS:
            return f"unknown criterion trigger '{trigger}'", trigger
        for field, predicate in (criterion.get("conditions") or {}).items():
            issue = _field_problem(field, predicate, version)
            if issue:
                return issue
    groups = value.get("requirements")
    if groups is not None:
        if not isinstance(groups, list) or not all(isinstance(g, list) for g in groups):
            return '"requirements" must be a list of lists of criterion names', "requirements"
        for group in groups:
            for name in group:
                if name not in found:
                    return f"requirements name '{name}', which is not a criterion", str(name)
    rewards = value.get("rewards")
    if rewards is not None and not isinstance(rewards, dict):
        return '"rewards" must be an object', "rewards"
    return None


def _field_problem(field: str, value: Any, version) -> tuple[str, str] | None:
    """A trigger's condition field: a ContextAwarePredicate (a list of loot conditions, or an entity
    predicate), an item predicate (``item``, ``rod``) or a list of them (``items``, ``ingredients``)."""
    if field in CONTEXT_FIELDS and isinstance(value, list):
        return conditions.problem(value, version)
    if field in CONTEXT_FIELDS and field != "location":  # ``location`` was a location predicate before 1.20
        return predicate_ids.entity_problem(value, version)
    if field in ("item", "rod"):
        return predicate_ids.item_problem(value, version)
    if field in ("items", "ingredients") and isinstance(value, list):
        return next(filter(None, (predicate_ids.item_problem(v, version) for v in value)), None)
    return None


def validate(doc: JsonDocument, version, what: str, diagnostics: list[Diagnostic]) -> bool:
    return conditions.report(doc, problem(doc.value, version) or conditions.sub_predicate_problem(doc.value, version),
                             what, diagnostics)
