"""Enchantment definition files (``data/<ns>/enchantment/*.json``, 1.21+) as the game decodes them:
a file that fails is an error at its JSON string and the enchantment does not exist (the game
refuses a world whose registries fail: "Errors in registry").

``check_enchantment(doc, what, diagnostics) -> bool`` checks Enchantment.DIRECT_CODEC's fields:
``description`` (a text component), ``supported_items`` and the optional ``primary_items`` (an
item id, a list of ids or a ``#tag``), ``weight`` 1-1024, ``max_level`` 1-255, ``min_cost`` and
``max_cost`` ({base, per_level_above_first} integers), ``anvil_cost`` 0 or more, ``slots`` (a list
of equipment slot groups), the optional ``exclusive_set`` (an enchantment id, a list or a
``#tag``) and ``effects`` (an object: its effect components are not checked here).

Sources: decompiled 1.21 world/item/enchantment/Enchantment.java (DIRECT_CODEC,
EnchantmentDefinition.CODEC, Cost.CODEC), world/entity/EquipmentSlotGroup.java (the group names),
core/RegistryCodecs.homogeneousList (an id, a list or a tag).
"""
from __future__ import annotations

from typing import Any

from mcfunction_parser.diagnostics import Diagnostic
from mcfunction_parser.pack.conditions import report
from mcfunction_parser.pack.text import JsonDocument

DATA_DRIVEN = (1, 21, 0)  # enchantments became a data-driven registry
SLOT_GROUPS = frozenset(("any", "mainhand", "offhand", "hand", "feet", "legs", "chest", "head", "armor", "body"))
SADDLE_GROUP = (1, 21, 5)  # EquipmentSlotGroup.SADDLE


def _is_int(value: Any) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


def _holder_set_problem(value: Any, field: str) -> str | None:
    """RegistryCodecs.homogeneousList: an id, a ``#tag`` or a list of ids."""
    if isinstance(value, str) and value:
        return None
    if isinstance(value, list) and all(isinstance(v, str) and v and not v.startswith("#") for v in value):
        return None
    return f'"{field}" must be an id, a #tag or a list of ids'


def _problem(value: Any, version) -> tuple[str, str | None] | None:
    if not isinstance(value, dict):
        return "an enchantment must be a JSON object", None
    if "description" not in value or not isinstance(value["description"], (str, dict, list)):
        return 'an enchantment needs "description": a text component', "description"
    for field in ("supported_items", "primary_items", "exclusive_set"):
        if field in value or field == "supported_items":
            found = _holder_set_problem(value.get(field), field)
            if found:
                return found, field
    for field, low, high in (("weight", 1, 1024), ("max_level", 1, 255), ("anvil_cost", 0, None)):
        number = value.get(field)
        if not _is_int(number) or number < low or (high is not None and number > high):
            bound = f"from {low} to {high}" if high is not None else f"{low} or more"
            return f'"{field}" must be an integer {bound}', field
    for field in ("min_cost", "max_cost"):
        cost = value.get(field)
        if not isinstance(cost, dict) or not _is_int(cost.get("base")) or not _is_int(cost.get("per_level_above_first")):
            return f'"{field}" must be an object with integers "base" and "per_level_above_first"', field
    slots = value.get("slots")
    groups = SLOT_GROUPS | ({"saddle"} if tuple(version) >= SADDLE_GROUP else set())
    if not isinstance(slots, list) or not all(isinstance(s, str) and s in groups for s in slots):
        return f'"slots" must be a list of equipment slot groups ({", ".join(sorted(groups))})', "slots"
    if "effects" in value and not isinstance(value["effects"], dict):
        return '"effects" must be an object of effect components', "effects"
    return None


def check_enchantment(doc: JsonDocument, what: str, version, diagnostics: list[Diagnostic]) -> bool:
    return report(doc, _problem(doc.value, version), what, diagnostics)
