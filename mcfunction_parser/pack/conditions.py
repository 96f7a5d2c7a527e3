"""Predicate JSON (loot item conditions) as the game loads it: which condition types exist in which
release, and the structural checks that make the game refuse a predicate file.

A predicate file (``data/<ns>/predicate/<path>.json``; ``predicates/`` before 1.21) holds one
condition object or a list of them (all must hold). Each condition names its type in
``condition``; the game's codec refuses a file whose type is unknown in that release or whose
required fields are missing or of the wrong kind ("Couldn't parse element ..."), and such a
predicate does not exist at run time. Sources: LootItemConditions (decompiled, the registry
of types: 1.19.4 registers ``alternative``, 1.20 ``any_of`` and ``all_of`` in its place, 1.21
``random_chance_with_enchanted_bonus`` in place of ``random_chance_with_looting`` and
``enchantment_active_check``). The one table of condition types: loot tables and item modifiers
(:mod:`mcfunction_parser.pack.loot`) check theirs with :func:`problem` too.
"""
from __future__ import annotations

from typing import Any

from mcfunction_parser import snbt
from mcfunction_parser.items import COMPONENTS_VERSION, sub_predicate_registered
from mcfunction_parser.diagnostics import ERROR, Diagnostic, Loc
from mcfunction_parser.reader import ParseError, Reader
from mcfunction_parser.pack.predicate_ids import condition_problem
from mcfunction_parser.pack.text import JsonDocument

Version = tuple[int, int, int]
OLDEST = (1, 13, 0)

# type -> (first release, first release without it): the types LootItemConditions registers
# (LootConditionManager in 1.13.2: random_chance, random_chance_with_looting, entity_properties,
# killed_by_player, entity_scores; 18w43a, 1.14, the rest of 1.14.4's), per snapshot 1.14.4 - 1.21.3
# and in 1.21.7, 1.21.11 and 26.1.2 (environment_attribute_check: 26.1-pre1 in SpyglassMC vanilla-mcdoc)
CONDITION_TYPES: dict[str, tuple[Version, Version | None]] = {
    "inverted": ((1, 14, 0), None),
    "alternative": ((1, 14, 0), (1, 20, 0)),
    "any_of": ((1, 20, 0), None),  # 23w18a, in alternative's place
    "all_of": ((1, 20, 0), None),
    "random_chance": (OLDEST, None),
    "random_chance_with_looting": (OLDEST, (1, 21, 0)),
    "random_chance_with_enchanted_bonus": ((1, 21, 0), None),  # 24w18a
    "entity_properties": (OLDEST, None),
    "killed_by_player": (OLDEST, None),
    "entity_scores": (OLDEST, None),
    "block_state_property": ((1, 14, 0), None),
    "match_tool": ((1, 14, 0), None),
    "table_bonus": ((1, 14, 0), None),
    "survives_explosion": ((1, 14, 0), None),
    "damage_source_properties": ((1, 14, 0), None),
    "location_check": ((1, 14, 0), None),
    "weather_check": ((1, 14, 0), None),
    "reference": ((1, 15, 0), None),  # 19w38a
    "time_check": ((1, 15, 0), None),  # 19w38a
    "value_check": ((1, 17, 0), None),  # 20w46a
    "enchantment_active_check": ((1, 21, 0), None),  # 24w18a
    "environment_attribute_check": ((26, 1, 0), None),
}

# fields the codec requires, per type (a missing one refuses the file)
_REQUIRED = {
    "inverted": ("term",), "alternative": ("terms",), "any_of": ("terms",), "all_of": ("terms",),
    "random_chance": ("chance",), "entity_properties": ("entity",), "entity_scores": ("entity", "scores"),
    "block_state_property": ("block",), "reference": ("name",), "time_check": ("value",),
    "value_check": ("value", "range"), "table_bonus": ("enchantment", "chances"),
    "random_chance_with_enchanted_bonus": ("enchantment", "enchanted_chance"),
    "random_chance_with_looting": ("chance", "looting_multiplier"), "enchantment_active_check": ("active",),
    "environment_attribute_check": ("attribute", "value"),
}
ENTITY_TARGETS = {"this", "attacker", "direct_attacker", "attacking_player",  # 1.21 names
                  "killer", "direct_killer", "killer_player"}  # before 1.21


def parse_inline(text: str):
    """An inline predicate (``execute if predicate {...}``, 1.20.5+): its NBT, read as JSON is read
    (see :class:`~mcfunction_parser.ast.ResourceOrInline`). Raises ValueError when it does not parse."""
    reader = Reader(text, Loc("<predicate>", 1, 1), (1, 21, 0))
    try:
        return snbt.value(reader)
    except ParseError as error:
        raise ValueError(error.message) from None


def condition_type(condition: Any) -> str:
    """The condition's type without the ``minecraft:`` namespace ('' when absent)."""
    kind = condition.get("condition") if isinstance(condition, dict) else None
    return kind.removeprefix("minecraft:") if isinstance(kind, str) else ""


def known_type(kind: str, version: Version) -> bool:
    span = CONDITION_TYPES.get(kind)
    return span is not None and span[0] <= version and (span[1] is None or version < span[1])


def problem(value: Any, version: Version) -> tuple[str, str] | None:
    """Why the game refuses this predicate (a condition or a list of them): (message, the JSON
    string to point at), or None when it loads."""
    return (_structure_problem(value, version) or sub_predicate_problem(value, version)
            or condition_problem(value, version))


def _structure_problem(value: Any, version: Version) -> tuple[str, str] | None:
    if isinstance(value, list):
        for item in value:
            found = _structure_problem(item, version)
            if found:
                return found
        return None
    if not isinstance(value, dict):
        return "a predicate must be a condition object or a list of them", ""
    raw = value.get("condition")
    if not isinstance(raw, str):
        return 'a condition needs "condition": its type (e.g. "minecraft:entity_properties")', ""
    kind = condition_type(value)
    if not known_type(kind, version):
        when = CONDITION_TYPES.get(kind)
        hint = ""
        if when is not None:
            hint = f" (it exists from {'.'.join(map(str, when[0]))}" + (
                f" until {'.'.join(map(str, when[1]))})" if when[1] else ")")
        return f"unknown predicate condition type '{raw}' in this release{hint}", raw
    for field in _REQUIRED.get(kind, ()):
        if field not in value:
            return f"condition '{raw}' needs the field \"{field}\"", raw
    if kind in ("entity_properties", "entity_scores") and value["entity"] not in ENTITY_TARGETS:
        return f"unknown entity target {value['entity']!r} (expected one of: {', '.join(sorted(ENTITY_TARGETS))})", \
            str(value["entity"])
    if kind == "inverted":
        return _structure_problem(value["term"], version)
    if kind in ("alternative", "any_of", "all_of"):
        if not isinstance(value["terms"], list):
            return f'"terms" of \'{raw}\' must be a list', "terms"
        return _structure_problem(value["terms"], version)
    return None


def validate(doc: JsonDocument, version: Version, what: str, diagnostics: list[Diagnostic]) -> bool:
    """Check a predicate file (``what`` names it in the message)."""
    return report(doc, problem(doc.value, version), what, diagnostics)


def sub_predicate_problem(value: Any, version: Version) -> tuple[str, str] | None:
    """An item sub-predicate the release does not register, anywhere in ``value``: every
    ``predicates`` object (1.20.5+) is read by the registry's dispatched map codec
    (ItemSubPredicate.CODEC / DataComponentPredicate's), which refuses an unknown name."""
    if isinstance(value, list):
        return next(filter(None, (sub_predicate_problem(v, version) for v in value)), None)
    if not isinstance(value, dict):
        return None
    subs = value.get("predicates")
    if isinstance(subs, dict) and version >= COMPONENTS_VERSION:
        for name in subs:
            full = name if ":" in name else "minecraft:" + name
            if not sub_predicate_registered(full, version):
                return f"unknown item sub-predicate '{name}' in this release", name
    return next(filter(None, (sub_predicate_problem(v, version) for v in value.values())), None)


def report(doc: JsonDocument, found: tuple[str, str] | None, what: str, diagnostics: list[Diagnostic]) -> bool:
    """True when ``found`` is None; else an error at the offending JSON string (the file's start
    when none is found) saying ``what`` fails to load."""
    if found is None:
        return True
    message, token = found
    offset = doc.find_string(token) if token else -1
    diagnostics.append(doc.diagnostic(ERROR, f"{what} fails to load: {message}", offset))
    return False
