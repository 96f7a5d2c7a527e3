"""Dimensions and dimension types as the game decodes what the emulator reads of them
(``data/<ns>/dimension/*.json``, ``data/<ns>/dimension_type/*.json``): a problem is an error at
its JSON string and the file is left out (the game refuses to load a world whose worldgen
registries fail: "Errors in registry").

- ``check_dimension(doc, types, diagnostics) -> bool``: LevelStem.CODEC: ``type`` (a dimension
  type id that exists, the pack's or the game's, or an inline type) and ``generator`` (an object
  with its ``type``).
- ``check_dimension_type(doc, diagnostics) -> bool``: the fields the emulator reads:
  ``coordinate_scale`` a number from 1e-5 to 3e7 (DimensionType.CODEC: Codec.doubleRange).
Other fields of a dimension type are not checked here.

Sources: decompiled 1.21 world/level/dimension/LevelStem.java (CODEC), DimensionType.java
(DIRECT_CODEC: coordinate_scale's range), BuiltinDimensionTypes.java (the game's types).
"""
from __future__ import annotations

from typing import Any

from mcfunction_parser.diagnostics import ERROR, Diagnostic
from mcfunction_parser.pack.text import JsonDocument

VANILLA_TYPES = frozenset(f"minecraft:{n}" for n in ("overworld", "overworld_caves", "the_nether", "the_end"))
SCALE_RANGE = (1.0e-5, 3.0e7)


def _id(name: str) -> str:
    return name if ":" in name else "minecraft:" + name


def _report(doc: JsonDocument, diagnostics: list[Diagnostic], what: str, message: str, token: str | None) -> bool:
    offset = doc.find_string(token) if token else -1
    diagnostics.append(doc.diagnostic(ERROR, f"{what} fails to load: {message}", offset))
    return False


def _type_problem(value: Any) -> tuple[str, str] | None:
    if not isinstance(value, dict):
        return "a dimension type must be a JSON object", None
    scale = value.get("coordinate_scale")
    if not isinstance(scale, (int, float)) or isinstance(scale, bool) or not SCALE_RANGE[0] <= scale <= SCALE_RANGE[1]:
        return '"coordinate_scale" must be a number from 1e-05 to 3e+07', "coordinate_scale"
    return None


def check_dimension_type(doc: JsonDocument, what: str, diagnostics: list[Diagnostic]) -> bool:
    found = _type_problem(doc.value)
    return True if found is None else _report(doc, diagnostics, what, *found)


def check_dimension(doc: JsonDocument, what: str, types, diagnostics: list[Diagnostic]) -> bool:
    """``types``: the dimension type ids the packs define (the game's own are known here)."""
    value = doc.value
    if not isinstance(value, dict):
        return _report(doc, diagnostics, what, "a dimension must be a JSON object", None)
    kind = value.get("type")
    if isinstance(kind, str):
        if _id(kind) not in types and _id(kind) not in VANILLA_TYPES:
            return _report(doc, diagnostics, what, f"unknown dimension type '{kind}'", kind)
    elif isinstance(kind, dict):
        found = _type_problem(kind)
        if found is not None:
            return _report(doc, diagnostics, what, *found)
    else:
        return _report(doc, diagnostics, what, 'a dimension needs "type": a dimension type id or object', "type")
    generator = value.get("generator")
    if not isinstance(generator, dict) or not isinstance(generator.get("type"), str):
        return _report(doc, diagnostics, what, 'a dimension needs "generator": an object with its "type"',
                       "generator")
    return True
