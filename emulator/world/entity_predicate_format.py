"""Entity predicates as 26.2 writes them, read into the form the evaluator knows.

From 26.2 an entity predicate is a map of sub-predicates (EntitySubPredicates), every key a
sub-predicate id with an optional ``minecraft:`` namespace: ``{"minecraft:entity_type":
"interaction", "entity_tags": {"all_of": ["a"]}, "type_specific/player": {"gamemode":
["creative"]}}``. ``entity_type`` is the old ``type``, ``type_specific/<kind>`` the old
``type_specific: {type: <kind>, ...}`` (``cube_mob`` the old ``slime``), ``entity_tags`` is new
(the entity's command tags: ``all_of``, ``any_of``, ``none_of``); the other ids keep the old
fields' names and contents. Nested entity predicates (``vehicle``, ``passenger``,
``looking_at`` ...) are read the same way when they are evaluated.

- ``classic(predicate, version)``: the predicate in the old field form (unchanged before 26.2).
- ``tags_match(value, entity)``: the ``entity_tags`` sub-predicate.
"""
from __future__ import annotations

from emulator.world.errors import Unmodelled

SUBPREDICATES_VERSION = (26, 2, 0)

# the sub-predicate ids that keep the old field's name and contents
_SAME = frozenset({"location", "stepping_on", "movement_affected_by", "distance", "movement", "effects", "nbt",
                   "flags", "equipment", "periodic_tick", "vehicle", "passenger", "targeted_entity", "team",
                   "slots", "components", "predicates", "entity_tags"})
_RENAMED = {"entity_type": "type"}
_TYPE_SPECIFIC = {"player": "player", "cube_mob": "slime", "fishing_hook": "fishing_hook",
                  "lightning": "lightning", "raider": "raider", "sheep": "sheep"}


def classic(predicate, version) -> dict:
    """``predicate`` with its 26.2 sub-predicate ids read as the old fields; an id the game does
    not register is not modelled (the game refuses the predicate)."""
    if not isinstance(predicate, dict) or tuple(version) < SUBPREDICATES_VERSION:
        return predicate
    out = {}
    for key, value in predicate.items():
        name = key.removeprefix("minecraft:")
        kind = name.removeprefix("type_specific/") if name.startswith("type_specific/") else None
        if kind in _TYPE_SPECIFIC and isinstance(value, dict):
            out["type_specific"] = {**value, "type": _TYPE_SPECIFIC[kind]}
        elif name in _RENAMED:
            out[_RENAMED[name]] = value
        elif name in _SAME:
            out[name] = value
        else:
            raise Unmodelled(f"entity sub-predicate '{key}'")
    return out


def tags_match(value: dict, entity) -> bool:
    """EntityTagPredicate: every ``all_of`` tag, at least one ``any_of`` tag (when given), no
    ``none_of`` tag."""
    tags = entity.tags
    any_of = value.get("any_of")
    return (all(t in tags for t in value.get("all_of", ()))
            and (any_of is None or any(t in tags for t in any_of))
            and not any(t in tags for t in value.get("none_of", ())))
