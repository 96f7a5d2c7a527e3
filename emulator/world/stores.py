"""``execute store ... entity|storage|block PATH TYPE SCALE`` and ``data get``: the numbers the game stores and returns.

Public functions
- ``stored_tag(type_name, value, scale)``: the tag ``execute store`` writes for a command result
  (or 1/0 for ``success``): ``(TYPE)((double) value * scale)`` with Java's narrowing casts:
  int/long truncate toward zero and saturate, NaN gives 0; byte/short go through ``(int)`` first and
  then keep the low 8/16 bits; float rounds to float32; double is stored as is.
- ``store(root, path, type_name, value, scale)``: write it; returns how many tags changed. A path
  error is swallowed as the game's store callback does, so nothing stored is just 0.
  (Into storage, an entity or a block through its accessor: :func:`emulator.commands.data.store`.)
- ``data_get(root, path)``: ``data get PATH`` result: ``Mth.floor`` of a number, the size of a
  list/array/compound, the length of a string (in UTF-16 units, as Java counts).
- ``data_get_scaled(root, path, scale)``: ``data get PATH SCALE``: ``Mth.floor(value * scale)``;
  non-numbers fail "Can't get PATH; only numeric tags are allowed".

Source: decompiled 1.21 ``server/commands/ExecuteCommand.java`` (``wrapStores``, ``storeData``) and
``server/commands/data/DataCommands.java`` (``getData``, ``getNumeric``, ``getSingleTag``).
"""
from __future__ import annotations

from mcfunction_parser import ast
from mcfunction_parser.nbt import Byte, Double, Float, Int, Long, Short
from emulator.world.semantics import (
    double_to_byte,
    double_to_int,
    double_to_long,
    double_to_short,
    mth_floor,
)
from emulator.world import mth, nbt_ops
from emulator.world.errors import CommandFailure

_CASTS = {
    "byte": lambda v: Byte(double_to_byte(v)),
    "short": lambda v: Short(double_to_short(v)),
    "int": lambda v: Int(double_to_int(v)),
    "long": lambda v: Long(double_to_long(v)),
    "float": lambda v: Float(float(mth.f32(v))),
    "double": lambda v: Double(v),
}


def stored_tag(type_name: str, value: int, scale: float):
    """The tag stored for ``value`` (an int result, or 1/0) with ``TYPE SCALE``."""
    return _CASTS[type_name](float(value) * scale)


def store(root, path: ast.NbtPath, type_name: str, value: int, scale: float) -> int:
    """Store into ``root`` at ``path``; failures are silent as in the game's store callback."""
    try:
        return nbt_ops.set_path(root, path, stored_tag(type_name, value, scale))
    except CommandFailure:
        return 0


def _single(root, path: ast.NbtPath):
    found = nbt_ops.get(root, path)
    if len(found) > 1:
        raise CommandFailure("commands.data.get.multiple")
    return found[0]


def java_length(text: str) -> int:
    """``String.length()``: UTF-16 code units (a character outside the BMP counts 2)."""
    return len(text.encode("utf-16-le")) // 2


def data_get(root, path: ast.NbtPath) -> int:
    tag = _single(root, path)
    if nbt_ops.is_numeric(tag):
        return mth_floor(nbt_ops.numeric_value(tag))
    if isinstance(tag, (list, dict)):
        return len(tag)
    if isinstance(tag, str):
        return java_length(tag)
    raise CommandFailure("commands.data.get.unknown", path.text)


def data_get_scaled(root, path: ast.NbtPath, scale: float) -> int:
    tag = _single(root, path)
    if not nbt_ops.is_numeric(tag):
        raise CommandFailure("commands.data.get.invalid", path.text)
    return mth_floor(nbt_ops.numeric_value(tag) * scale)
