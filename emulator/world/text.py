"""Numbers and tags as text, the way the game's Java prints them.

- ``java_double_string(x)`` / ``java_float_string(x)``: ``Double.toString`` / ``Float.toString``
  (Java 19+, which 1.20.5+ requires): the shortest digits that read back to the same value; plain
  decimal (at least one fractional digit) for 1e-3 <= |x| < 1e7, else ``d.dddE±n``;
  ``NaN``, ``Infinity``, ``-0.0``.

Source: decompiled 1.21 nbt/StringTagVisitor.java (visitFloat/visitDouble append the Java number
and the suffix), java.lang.Double/Float.toString.
"""
from __future__ import annotations

import json
import math
from decimal import ROUND_HALF_EVEN, Decimal

import numpy as np

from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.nbt import Compound, List
from mcfunction_parser.reader import ParseError, Reader
from mcfunction_parser.snbt import value as snbt_value

from emulator.world import translations


def _java_text(value: float, shortest: str, reads_back) -> str:
    if math.isnan(value):
        return "NaN"
    if math.isinf(value):
        return "Infinity" if value > 0 else "-Infinity"
    sign = "-" if math.copysign(1.0, value) < 0 else ""
    if value == 0.0:
        return sign + "0.0"
    exact = _digits(abs(value), Decimal(shortest).copy_abs().normalize(), reads_back)
    digits = "".join(map(str, exact.as_tuple().digits))
    exponent = exact.as_tuple().exponent + len(digits) - 1  # scientific exponent of the first digit
    if 1e-3 <= abs(value) < 1e7:
        text = format(exact, "f")
        return sign + (text if "." in text else text + ".0")
    return f"{sign}{digits[0]}.{digits[1:] or '0'}E{exponent}"


def _digits(value: float, shortest: Decimal, reads_back) -> Decimal:
    """Java's choice of digits: the shortest decimal that reads back, except that a one-digit
    result gives way to the closest two-digit one (``Double.MIN_VALUE`` prints ``4.9E-324``)."""
    if len(shortest.as_tuple().digits) > 1:
        return shortest
    exact = Decimal(value)
    unit = Decimal(1).scaleb(exact.adjusted() - 1)  # two digits at the magnitude of the value itself
    two = (exact / unit).quantize(Decimal(1), rounding=ROUND_HALF_EVEN) * unit
    if reads_back(two) and abs(two - exact) < abs(shortest - exact):
        return two.normalize()
    return shortest


def java_double_string(x: float) -> str:
    return _java_text(x, repr(x), lambda d: float(d) == x)


def java_float_string(x) -> str:
    value = np.float32(x)
    return _java_text(float(value), np.format_float_positional(value, unique=True, trim="-"),
                      lambda d: np.float32(float(d)) == value)


def read_component(text: str):
    """A text component as written: JSON, else SNBT (1.21.5+ commands write components as SNBT),
    as plain Python values (dicts, lists, strings, numbers); None when it is neither."""
    try:
        return json.loads(text)
    except ValueError:
        pass
    reader = Reader(text, Loc("<text>", 1, 1), (1, 21, 5))
    try:
        value = snbt_value(reader)
    except ParseError:
        return None
    return plain_value(value) if not text[reader.pos:].strip() else None


RESOLVED = ("score", "selector", "nbt")  # the contents ComponentUtils.updateForEntity resolves


def needs_resolving(component) -> bool:
    """Whether a component (plain values) holds a score, selector or nbt part, itself, in its extras
    or in its translation's arguments."""
    if isinstance(component, list):
        return any(needs_resolving(c) for c in component)
    if isinstance(component, dict):
        return (any(k in component for k in RESOLVED) or needs_resolving(component.get("extra", []))
                or needs_resolving(component.get("with", [])))
    return False


def plain_value(tag):
    """An NBT tag as the plain Python value a JSON component would have."""
    if isinstance(tag, Compound):
        return {k: plain_value(v) for k, v in tag.items()}
    if isinstance(tag, List):
        return [plain_value(v) for v in tag]
    if isinstance(tag, str):
        return str(tag)
    return int(tag) if isinstance(tag, int) else float(tag)


_STYLE_FLAGS = ("bold", "italic", "underlined", "strikethrough", "obfuscated")


def component_value(value):
    """A text component (plain values or NBT) in one form for each Component the codec decodes it
    to, so that two compare equal when the game's Components do (MutableComponent.equals: contents,
    style, siblings): a string is ``{"text": s}``, a list its first element with the rest appended
    to its siblings, ``type`` dropped, the style flags booleans, empty ``extra`` dropped."""
    value = plain_value(value) if not isinstance(value, (dict, list, str, int, float)) else value
    if isinstance(value, str):
        return {"text": value}
    if isinstance(value, list):
        if not value:
            return {"text": ""}
        first = component_value(value[0])
        siblings = first.get("extra", []) + [component_value(v) for v in value[1:]]
        return {**first, "extra": siblings} if siblings else first
    if not isinstance(value, dict):
        return {"text": str(value)}
    out = {k: (bool(v) if k in _STYLE_FLAGS else v) for k, v in value.items() if k != "type"}
    siblings = [component_value(v) for v in out.pop("extra", [])]
    if "with" in out and isinstance(out["with"], list):
        out["with"] = [v if isinstance(v, (int, float)) else component_value(v) for v in out["with"]]
    return {**out, "extra": siblings} if siblings else out


def plain_text(text: str, release=None) -> str:
    """The plain text of a text component as written (a string, list or object with its extras, in
    JSON or SNBT; a ``translate`` reads as :func:`emulator.world.translations.translated` does in
    ``release``, None: without the game's strings), else the text as written."""
    value = read_component(text)
    return text if value is None else _plain(value, release)


def _plain(value, release) -> str:
    if isinstance(value, str):
        return value
    if isinstance(value, bool):  # a primitive translation argument: its Java toString
        return "true" if value else "false"
    if isinstance(value, float):
        return java_double_string(value)
    if isinstance(value, list):
        return "".join(_plain(v, release) for v in value)
    if isinstance(value, dict):
        # ComponentSerialization: the first content type whose field is there, text before
        # translate before keybind (an unresolved score, selector or nbt reads as nothing)
        if "text" in value or "translate" not in value and "keybind" not in value:
            own = str(value.get("text", ""))
        elif "translate" in value:
            own = translations.translated(value, release, lambda argument: _plain(argument, release))
        else:
            own = translations.keybind(value, release)
        return own + "".join(_plain(v, release) for v in value.get("extra", []))
    return str(value)
