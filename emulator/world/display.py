"""Display entities' own NBT (``item_display``, ``block_display``, ``text_display``).

A display always saves its render fields, so ``data modify entity @s transformation.translation
...`` works on a full compound even when the entity was summoned without one. Loading reads each
field the way ``Display.readAdditionalSaveData`` does: a field of the wrong kind keeps the current
value, numbers are converted to the saved type, ``teleport_duration`` is clamped to 0..59,
``start_interpolation`` is read but never saved, and a missing ``brightness`` clears it.

- ``DISPLAY_TYPES``: the three display entity ids.
- ``default_fields(type_id)``: the fields a new display saves.
- ``read_fields(type_id, nbt, previous)``: the fields after loading ``nbt`` over ``previous``.
- ``NOT_SAVED``: fields a display reads but does not save.
- ``transformation_columns(tag)`` / ``transformation_tag(values)``: the decomposed ``transformation``
  as the 14 numbers the entity table keeps (translation, left rotation, scale, right rotation) and back.

``transformation`` is read in its decomposed form (quaternion or ``{angle, axis}`` rotations) or as
16 numbers, a row-major matrix decomposed as the game decomposes it (:mod:`emulator.world.matrix`);
it is saved decomposed. Item and block contents (``item``, ``block_state``, ``text``) are kept as
given.

Source: decompiled 1.21 world/entity/Display.java (defineSynchedData, readAdditionalSaveData,
addAdditionalSaveData) and com/mojang/math/Transformation.java (EXTENDED_CODEC).
"""
from __future__ import annotations

from mcfunction_parser.nbt import Compound, Float, Int, List, String
from emulator.world import matrix, mth
from emulator.world.nbt_ops import copy_tag, is_numeric, narrow, numeric_value

DISPLAY_TYPES = ("minecraft:item_display", "minecraft:block_display", "minecraft:text_display")
NOT_SAVED = ("start_interpolation",)  # read by load, never written back
BILLBOARDS = ("fixed", "vertical", "horizontal", "center")
_FLOATS = {"view_range": 1.0, "shadow_radius": 0.0, "shadow_strength": 1.0, "width": 0.0, "height": 0.0}
_INTS = {"interpolation_duration": 0, "teleport_duration": 0, "glow_color_override": -1}
# Transformation's record fields in codec order, with their sizes and defaults.
_TRANSFORM = (("translation", (0.0, 0.0, 0.0)), ("left_rotation", (0.0, 0.0, 0.0, 1.0)),
              ("scale", (1.0, 1.0, 1.0)), ("right_rotation", (0.0, 0.0, 0.0, 1.0)))
_TYPE_DEFAULTS = {"minecraft:item_display": {"item_display": String("none")},
                  "minecraft:block_display": {"block_state": Compound(Name=String("minecraft:air"))}}


def _floats(values) -> List:
    return List(Float(float(mth.f32(v))) for v in values)


def default_fields(type_id: str) -> Compound:
    fields = Compound(transformation=Compound((k, _floats(v)) for k, v in _TRANSFORM))
    fields["billboard"] = String("fixed")
    fields.update((k, Int(v)) for k, v in _INTS.items())
    fields.update((k, Float(v)) for k, v in _FLOATS.items())
    fields.update((k, copy_tag(v)) for k, v in _TYPE_DEFAULTS.get(type_id, {}).items())
    return fields


def _numbers(value, size: int) -> list | None:
    if isinstance(value, List) and len(value) == size and all(is_numeric(v) for v in value):
        return [numeric_value(v) for v in value]
    return None


def _part(key: str, value, size: int) -> list | None:
    """A part of the decomposed form: a numeric list of the right size, or a rotation written as
    ``{angle, axis: [x, y, z]}`` (ExtraCodecs.AXISANGLE4F)."""
    numbers = _numbers(value, size)
    if numbers is None and key.endswith("rotation") and isinstance(value, Compound) and is_numeric(value.get("angle")):
        axis = _numbers(value.get("axis"), 3)
        if axis is not None:
            return list(matrix.axis_angle(numeric_value(value["angle"]), axis))
    return numbers


def _transformation(value, previous: Compound) -> Compound:
    """Transformation.EXTENDED_CODEC: the decomposed form, else 16 numbers (a row-major matrix the
    game decomposes, emulator.world.matrix); anything else keeps the previous value."""
    matrix_values = _numbers(value, 16)
    if matrix_values is not None:
        return Compound((key, _floats(part)) for (key, _), part in zip(_TRANSFORM, matrix.decompose(matrix_values)))
    if not isinstance(value, Compound):
        return copy_tag(previous)
    parts = Compound()
    for key, default in _TRANSFORM:
        part = _part(key, value.get(key), len(default))
        if part is None:
            return copy_tag(previous)
        parts[key] = _floats(part)
    return parts


def transformation_columns(tag: Compound) -> list[float]:
    """The decomposed transformation (as ``read_fields`` leaves it) as 14 numbers, in codec order."""
    return [float(v) for key, _ in _TRANSFORM for v in tag[key]]


def transformation_tag(values) -> Compound:
    """The transformation compound of 14 float32 numbers in codec order (as saved)."""
    parts, i = Compound(), 0
    for key, default in _TRANSFORM:
        parts[key] = List(Float(v) for v in values[i:i + len(default)])
        i += len(default)
    return parts


def _parts() -> dict[str, tuple[int, int]]:
    parts, start = {}, 0
    for key, default in _TRANSFORM:
        parts[key] = (start, len(default))
        start += len(default)
    return parts


TRANSFORM_PARTS = _parts()  # part -> (its first of the 14 numbers, its size)


def read_fields(type_id: str, nbt: Compound, previous: Compound) -> Compound:
    """The display fields after ``readAdditionalSaveData(nbt)`` on an entity that had ``previous``."""
    fields = default_fields(type_id)
    fields.update((k, copy_tag(v)) for k, v in previous.items() if k in fields or k == "brightness")
    if "transformation" in nbt:
        fields["transformation"] = _transformation(nbt["transformation"], fields["transformation"])
    for key in _INTS:
        if is_numeric(nbt.get(key)):
            value = narrow(nbt[key], Int)
            fields[key] = Int(min(max(value, 0), 59) if key == "teleport_duration" else value)
    for key in _FLOATS:
        if is_numeric(nbt.get(key)):
            fields[key] = Float(float(mth.f32(numeric_value(nbt[key]))))
    if isinstance(nbt.get("billboard"), String) and nbt["billboard"] in BILLBOARDS:
        fields["billboard"] = String(nbt["billboard"])
    brightness = nbt.get("brightness")
    fields.pop("brightness", None)
    if isinstance(brightness, Compound) and all(
            is_numeric(brightness.get(k)) and 0 <= narrow(brightness[k], Int) <= 15 for k in ("sky", "block")):
        fields["brightness"] = Compound(sky=Int(narrow(brightness["sky"], Int)), block=Int(narrow(brightness["block"], Int)))
    for key in _TYPE_DEFAULTS.get(type_id, {}):
        if key in nbt:
            fields[key] = copy_tag(nbt[key])
    return fields
