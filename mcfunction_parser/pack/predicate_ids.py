"""The ids inside predicates, checked as the game's codecs decode them: a predicate file, a loot
condition or an advancement criterion naming an item, entity type or block the release does not
register, a data component type it does not have, or a slot range that does not exist, fails to
load ("Unknown registry key ...", "Unknown element name ...").

- ``condition_problem(condition, version)``: a loot condition (or a list of them), walked into
  its entity, location, item and block predicates.
- ``entity_problem``, ``item_problem``: one entity or item predicate (advancement triggers' fields).
Each returns (message, the JSON string to point at) or None.

Sources (decompiled 1.21, advancements/critereon/*): ItemPredicate.CODEC (``items``:
RegistryCodecs.homogeneousList(ITEM), ``components``: DataComponentPredicate.CODEC keyed by
DataComponentType.CODEC), EntityTypePredicate.CODEC (homogeneousList(ENTITY_TYPE)),
BlockPredicate.CODEC (homogeneousList(BLOCK)), SlotsPredicate.CODEC (Codec.unboundedMap keyed by
SlotRanges.CODEC: StringRepresentable.fromValues), EntityPredicate/LocationPredicate's nested
predicates, LootItemBlockStatePropertyCondition (``block``: BLOCK.holderByNameCodec). A ``#tag``
is not checked here (registry tags are). Only the static registries are checked (items, entity
types, blocks): a pack may add to the data-driven ones (biomes, enchantments ...).
"""
from __future__ import annotations

from typing import Any

from mcfunction_parser import gamedata
from mcfunction_parser.items import COMPONENTS_VERSION, SLOTS, component_problem

Version = tuple[int, int, int]
Problem = tuple[str, str] | None
_WHAT = {"item": "item", "entity_type": "entity type", "block": "block"}


def _first(found) -> Problem:
    return next(filter(None, found), None)


def unknown_id(registry: str, name: Any, version: Version) -> Problem:
    """``name`` (an id, not a ``#tag``) missing from the release's own ``registry``; None when it is
    there, is a tag, or dpemu has no data of that very release (a newer one may add it)."""
    if not isinstance(name, str) or name.startswith("#"):
        return None
    try:
        release, exact = gamedata.registry_release(version)
    except gamedata.GameDataMissing:
        return None
    known = gamedata.registry(registry, release)
    namespace, _, path = (name if ":" in name else "minecraft:" + name).partition(":")
    if not exact or not known or (namespace == "minecraft" and path in known):
        return None
    return f"unknown {_WHAT[registry]} '{name}'", name


def _holders(registry: str, value: Any, version: Version) -> Problem:
    """A HolderSet: an id, ``#tag`` or a list of ids."""
    values = value if isinstance(value, list) else [value]
    return _first(unknown_id(registry, v, version) for v in values)


def condition_problem(condition: Any, version: Version) -> Problem:
    if isinstance(condition, list):
        return _first(condition_problem(c, version) for c in condition)
    if not isinstance(condition, dict):
        return None
    kind = str(condition.get("condition", "")).removeprefix("minecraft:")
    if kind == "inverted":
        return condition_problem(condition.get("term"), version)
    if kind in ("all_of", "any_of", "alternative"):
        return condition_problem(condition.get("terms"), version)
    predicate = condition.get("predicate")
    if kind == "entity_properties":
        return entity_problem(predicate, version)
    if kind == "location_check":
        return _location_problem(predicate, version)
    if kind == "match_tool":
        return item_problem(predicate, version)
    if kind == "block_state_property":
        return unknown_id("block", condition.get("block"), version)
    if kind == "damage_source_properties" and isinstance(predicate, dict):
        return _first(entity_problem(predicate.get(key), version) for key in ("source_entity", "direct_entity"))
    return None


def entity_problem(predicate: Any, version: Version) -> Problem:
    """An entity predicate object (a list is a ContextAwarePredicate's loot conditions)."""
    if isinstance(predicate, list):
        return condition_problem(predicate, version)
    if not isinstance(predicate, dict):
        return None
    found = []
    if "type" in predicate:
        found.append(_holders("entity_type", predicate["type"], version))
    for key in ("vehicle", "passenger", "targeted_entity"):
        found.append(entity_problem(predicate.get(key), version))
    for key in ("location", "stepping_on", "movement_affected_by"):
        found.append(_location_problem(predicate.get(key), version))
    equipment = predicate.get("equipment")
    if isinstance(equipment, dict):
        found.extend(item_problem(value, version) for value in equipment.values())
    slots = predicate.get("slots")
    if isinstance(slots, dict) and version >= COMPONENTS_VERSION:
        found.extend(_slot_problem(name, version) or item_problem(value, version) for name, value in slots.items())
    specific = predicate.get("type_specific", predicate.get("player"))
    if isinstance(specific, dict):
        found.append(entity_problem(specific.get("looking_at"), version))
    components = predicate.get("components")
    if isinstance(components, dict) and version >= (1, 21, 5):
        found.extend(_component(name, version) for name in components)
    return _first(found)


def _slot_problem(name: str, version: Version) -> Problem:
    span = SLOTS.get(name)
    if span is None or version < span[1] or (span[2] is not None and version >= span[2]):
        return f"unknown slot range '{name}'", name
    return None


def _component(name: str, version: Version) -> Problem:
    found = component_problem(name if ":" in name else "minecraft:" + name, version)
    return (found[1], name) if found is not None and found[0] == "error" else None


def item_problem(predicate: Any, version: Version) -> Problem:
    if not isinstance(predicate, dict):
        return None
    found = [_holders("item", predicate.get("items", predicate.get("item")), version)]
    components = predicate.get("components")
    if isinstance(components, dict) and version >= COMPONENTS_VERSION:
        found.extend(_component(name, version) for name in components)
    return _first(found)


def _location_problem(predicate: Any, version: Version) -> Problem:
    if not isinstance(predicate, dict):
        return None
    block = predicate.get("block")
    if not isinstance(block, dict):
        return None
    return _holders("block", block.get("blocks", block.get("block")), version)
