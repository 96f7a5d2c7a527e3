"""SNBT values read as the game's codecs read them (Mojang's DataFixerUpper through NbtOps), for
the values commands give in SNBT: item components (``diamond_sword[damage=3]``) and, from 1.20.5,
particle options (``dust{color:[1,0,0],scale:1}``).

A shape is a function ``(value, version) -> problem or None``. As NbtOps reads them: ``Codec.INT``
and ``Codec.FLOAT`` take any numeric tag (``3.5`` is the int 3, ``1b`` is 1) and nothing else;
``Codec.BOOL`` a numeric tag; a list codec a list or a numeric array; a record (MapCodec) a
compound, where a missing required field fails and fields it does not know are ignored.
"""
from __future__ import annotations

from typing import Callable

from .nbt import ByteArray, Compound, IntArray, List, LongArray, String
from .snbt import to_float32

Version = tuple[int, int, int]
Shape = Callable[[object, Version], "str | None"]
_LISTS = (List, ByteArray, IntArray, LongArray)
RGB_AS_INT = (1, 21, 2)  # 24w36a: dust colours are ExtraCodecs.RGB_COLOR_CODEC (an int, or the old list)


def is_number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def number(value, version) -> str | None:
    return None if is_number(value) else f"expected a number, got {kind(value)}"


def int_between(low: int, high: int | None = None) -> Shape:
    """Codec.INT, ExtraCodecs.NON_NEGATIVE_INT / POSITIVE_INT or intRange(low, high): Number.intValue()
    then the bounds (``high`` None: none above)."""
    def shape(value, version):
        if not is_number(value):
            return f"expected an integer, got {kind(value)}"
        if high is None and int(value) < low:
            return f"expected an integer of at least {low}, got {int(value)}"
        if high is not None and not low <= int(value) <= high:
            return f"expected an integer from {low} to {high}, got {int(value)}"
        return None
    return shape


def int_at_least(low: int) -> Shape:
    return int_between(low)


def float_between(low: float, high: float) -> Shape:
    """Codec.FLOAT validated to [low, high] (the value as a float)."""
    def shape(value, version):
        if not is_number(value):
            return f"expected a number, got {kind(value)}"
        if not to_float32(low) <= to_float32(float(value)) <= to_float32(high):
            return f"expected a number from {low} to {high}, got {value}"
        return None
    return shape


def boolean(value, version) -> str | None:
    return None if is_number(value) else f"expected true or false, got {kind(value)}"


def string(value, version) -> str | None:
    return None if isinstance(value, str) else f"expected a string, got {kind(value)}"


def compound(value, version) -> str | None:
    return None if isinstance(value, Compound) else f"expected a compound {{...}}, got {kind(value)}"


def a_list(value, version) -> str | None:
    return None if isinstance(value, _LISTS) else f"expected a list [...], got {kind(value)}"


def list_of(element: Shape) -> Shape:
    """``element.listOf()``: a list whose every entry reads as ``element``."""
    def shape(value, version):
        if not isinstance(value, _LISTS):
            return f"expected a list [...], got {kind(value)}"
        return next((f"entry {i}: {p}" for i, p in ((i, element(v, version)) for i, v in enumerate(value)) if p),
                    None)
    return shape


def one_of(*words: str) -> Shape:
    """A StringRepresentable enum: one of ``words``."""
    def shape(value, version):
        if isinstance(value, str) and value in words:
            return None
        return f"expected one of {', '.join(words)}, got {_show(value)}"
    return shape


def numbers(count: int) -> Shape:
    """ExtraCodecs.VECTOR3F / VECTOR4F: a list of exactly ``count`` numbers."""
    def shape(value, version):
        if not isinstance(value, _LISTS) or len(value) != count or not all(is_number(v) for v in value):
            return f"expected a list of {count} numbers, got {_show(value)}"
        return None
    return shape


def either(*shapes: Shape, what: str) -> Shape:
    """Codec.withAlternative: the first shape that reads the value. When none does, a problem past the
    value's kind (an unknown id, a missing field) is reported rather than the kinds expected."""
    def shape(value, version):
        problems = []
        for alternative in shapes:
            problem = alternative(value, version)
            if problem is None:
                return None
            problems.append(problem)
        return next((p for p in problems if not p.startswith("expected ")), f"expected {what}, got {_show(value)}")
    return shape


def fields(*required: tuple[str, Shape], optional: tuple[tuple[str, Shape], ...] = ()) -> Shape:
    """A record (RecordCodecBuilder.mapCodec): a compound with the required fields, each of its shape."""
    def shape(value, version):
        if not isinstance(value, Compound):
            return f"expected a compound {{...}}, got {kind(value)}"
        for name, field_shape in required:
            if name not in value:
                return f"missing field '{name}'"
        for name, field_shape in (*required, *optional):
            if name in value:
                problem = field_shape(value[name], version)
                if problem:
                    return f"'{name}': {problem}"
        return None
    return shape


def since(release: Version, new: Shape, old: Shape) -> Shape:
    """``new`` from ``release``, ``old`` before it."""
    def shape(value, version):
        return (new if version >= release else old)(value, version)
    return shape


def kind(value) -> str:
    """What a value is, for a message."""
    if isinstance(value, str):
        return f"the string {_show(value)}"
    if isinstance(value, Compound):
        return "a compound"
    if isinstance(value, _LISTS):
        return "a list"
    return f"the number {value}"


def _show(value) -> str:
    text = repr(str(value)) if isinstance(value, str) else str(value)
    return text if len(text) <= 40 else text[:37] + "..."


# ----------------------------------------------------------------------------- shared shapes

RGB = since(RGB_AS_INT, either(int_at_least(-2**31), numbers(3), what="an RGB int or a list of 3 numbers"),
            numbers(3))
ARGB = either(int_at_least(-2**31), numbers(4), what="an ARGB int or a list of 4 numbers")
TEXT_AS_SNBT = (1, 21, 5)  # 25w02a: components hold text as SNBT, not a JSON string
TEXT = since(TEXT_AS_SNBT, either(string, compound, a_list, what="a text component"), string)
