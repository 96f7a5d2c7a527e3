"""Rotations, directions, local coordinates and ``facing``, with the game's float/double mix.

Conventions: a rotation is ``(yaw, pitch)`` as float32 (``numpy.float32``); yaw is the entity's
``yRot`` (0 = south/+z, 90 = west/-x), pitch is ``xRot`` (positive looks down). Positions and
directions are tuples of three Python floats (doubles).

Public functions
- ``direction_from_rotation(yaw, pitch)``: ``Vec3.directionFromRotation`` (unit vector).
- ``view_vector(yaw, pitch)``: ``Entity.calculateViewVector`` (what ``getLookAngle`` returns).
- ``local_to_world(origin, yaw, pitch, left, up, forwards)``: ``^left ^up ^forwards`` from an
  origin (the execution position with its anchor applied), ``LocalCoordinates.getPosition``.
- ``facing_rotation(origin, target)``: the ``(yaw, pitch)`` that looks from ``origin`` at
  ``target``; ``execute facing``, ``tp ... facing`` and ``Entity.lookAt`` all use this formula
  (``facing_angles`` of the offset, the form the numba VM compiles).
- ``relative_rotation(base_yaw, base_pitch, yaw_coord, pitch_coord)``: a rotation argument
  (``~10 ~``) resolved against the execution rotation: ``(float)(value + (double)base)``.
- ``load_rotation(current, loaded)``: what loading ``Rotation`` NBT leaves (finite values, ``% 360``).
- ``teleport_rotation(yaw, pitch)``: what ``tp`` stores: both wrapped, then pitch clamped to ±90.

Sources (decompiled 1.21, Yeet-Masta/MCP-1.21): ``world/phys/Vec3.java``,
``commands/arguments/coordinates/LocalCoordinates.java``, ``WorldCoordinates.java``,
``commands/CommandSourceStack.java`` (``facing``), ``world/entity/Entity.java`` (``lookAt``,
``calculateViewVector``, ``setRot``, ``load``, ``teleportTo``), ``server/commands/TeleportCommand.java``.
"""
from __future__ import annotations

import math

import numpy as np

from emulator.world import mth

F32 = np.float32
_RIGHT_ANGLE = F32(90.0)
_RAD_TO_DEG_D = float(mth.RAD_TO_DEG)  # 57.2957763671875
_HUGE = F32(1e30)  # below this, the sine table's index cannot overflow float32


def direction_from_rotation(yaw, pitch) -> tuple[float, float, float]:
    """``Vec3.directionFromRotation(pitch, yaw)``: float products widened to double."""
    yaw_rad = -F32(yaw) * mth.DEG_TO_RAD - mth.PI_F
    pitch_rad = -F32(pitch) * mth.DEG_TO_RAD
    cos_yaw, sin_yaw = mth.cos(yaw_rad), mth.sin(yaw_rad)
    cos_pitch, sin_pitch = -mth.cos(pitch_rad), mth.sin(pitch_rad)
    return float(sin_yaw * cos_pitch), float(sin_pitch), float(cos_yaw * cos_pitch)


def view_vector(yaw, pitch) -> tuple[float, float, float]:
    """``Entity.calculateViewVector(xRot, yRot)``."""
    pitch_rad = F32(pitch) * mth.DEG_TO_RAD
    yaw_rad = -F32(yaw) * mth.DEG_TO_RAD
    cos_yaw, sin_yaw = mth.cos(yaw_rad), mth.sin(yaw_rad)
    cos_pitch, sin_pitch = mth.cos(pitch_rad), mth.sin(pitch_rad)
    return float(sin_yaw * cos_pitch), float(-sin_pitch), float(cos_yaw * cos_pitch)


def local_to_world(origin, yaw, pitch, left: float, up: float, forwards: float) -> tuple[float, float, float]:
    """``^left ^up ^forwards`` relative to ``origin`` facing ``(yaw, pitch)``."""
    x, y, z = origin
    yaw, pitch = F32(yaw), F32(pitch)
    if -_HUGE < yaw < _HUGE and -_HUGE < pitch < _HUGE:
        return local_offset(x, y, z, yaw, pitch, left, up, forwards)
    with np.errstate(over="ignore", invalid="ignore"):  # the sine table's index overflows, as in Java
        return local_offset(x, y, z, yaw, pitch, left, up, forwards)


def local_offset(x: float, y: float, z: float, yaw: np.float32, pitch: np.float32, left: float, up: float,
                 forwards: float) -> tuple[float, float, float]:
    """``LocalCoordinates.getPosition`` from ``(x, y, z)`` (scalars only: the numba VM compiles this
    function as is). The basis vectors are float products widened to double; the rest is double
    arithmetic, summed in the game's order (forwards, then up, then left)."""
    yaw_rad = (yaw + _RIGHT_ANGLE) * mth.DEG_TO_RAD
    cos_yaw, sin_yaw = mth.cos_of(yaw_rad), mth.sin_of(yaw_rad)
    pitch_rad = -pitch * mth.DEG_TO_RAD
    cos_pitch, sin_pitch = mth.cos_of(pitch_rad), mth.sin_of(pitch_rad)
    up_rad = (-pitch + _RIGHT_ANGLE) * mth.DEG_TO_RAD
    cos_up, sin_up = mth.cos_of(up_rad), mth.sin_of(up_rad)
    # np.float64, not float(): numba's float() of a float32 stays a float32
    fx, fy, fz = np.float64(cos_yaw * cos_pitch), np.float64(sin_pitch), np.float64(sin_yaw * cos_pitch)
    ux, uy, uz = np.float64(cos_yaw * cos_up), np.float64(sin_up), np.float64(sin_yaw * cos_up)
    # the left axis: the cross product forwards x up, times -1.0
    lx = (fy * uz - fz * uy) * -1.0
    ly = (fz * ux - fx * uz) * -1.0
    lz = (fx * uy - fy * ux) * -1.0
    return (float(x + (fx * forwards + ux * up + lx * left)), float(y + (fy * forwards + uy * up + ly * left)),
            float(z + (fz * forwards + uz * up + lz * left)))


def facing_rotation(origin, target, float_horizontal: bool = False) -> tuple[np.float32, np.float32]:
    """The rotation looking from ``origin`` to ``target`` (``CommandSourceStack.facing``).

    ``pitch = wrapDegrees((float) -(atan2(dy, horizontal) * RAD_TO_DEG))`` and
    ``yaw = wrapDegrees((float)(atan2(dz, dx) * RAD_TO_DEG) - 90.0F)``, where ``RAD_TO_DEG`` is the
    float ``180F / (float)PI`` widened to double (57.2957763671875): one multiplication. (Vineflower
    prints that constant as ``180.0F / (float)Math.PI`` without parentheses; CFR decompiles of the
    same method show the single constant.) ``float_horizontal``: 1.17 and older rounded the
    horizontal distance to float (``Mth.sqrt``); 1.18+ use ``Math.sqrt``.
    """
    dx, dy, dz = (t - o for t, o in zip(target, origin))
    if float_horizontal:
        horizontal = float(mth.f32(math.sqrt(dx * dx + dz * dz)))
        pitch = mth.wrap_degrees_f(mth.f32(-(mth.atan2(dy, horizontal) * _RAD_TO_DEG_D)))
        return mth.wrap_degrees_f(mth.f32(mth.atan2(dz, dx) * _RAD_TO_DEG_D) - _RIGHT_ANGLE), pitch
    return facing_angles(dx, dy, dz)


def facing_angles(dx: float, dy: float, dz: float) -> tuple[np.float32, np.float32]:
    """``facing_rotation`` of the offset ``(dx, dy, dz)`` (1.18+: the horizontal distance in double;
    scalars only: the numba VM compiles this function as is). Both angles are at most 180 degrees
    before the cast, so the float casts cannot overflow."""
    horizontal = math.sqrt(dx * dx + dz * dz)
    pitch = mth.wrap_degrees_f(np.float32(-(mth.atan2(dy, horizontal) * _RAD_TO_DEG_D)))
    yaw = mth.wrap_degrees_f(np.float32(mth.atan2(dz, dx) * _RAD_TO_DEG_D) - _RIGHT_ANGLE)
    return yaw, pitch


def resolve_angle(base, value: float, relative: bool) -> np.float32:
    """One rotation coordinate: ``(float) WorldCoordinate.get((double) base)``."""
    return mth.f32(value + float(F32(base)) if relative else value)


def relative_rotation(base_yaw, base_pitch, yaw_coord, pitch_coord) -> tuple[np.float32, np.float32]:
    """A rotation argument (``Vec2`` of ``Coord``: ``abs`` or ``rel``) against the execution rotation."""
    return (
        resolve_angle(base_yaw, yaw_coord.value, yaw_coord.kind == "rel"),
        resolve_angle(base_pitch, pitch_coord.value, pitch_coord.kind == "rel"),
    )


def load_rotation(current, loaded) -> tuple[np.float32, np.float32]:
    """Rotation after loading NBT (``Entity.load``): each loaded component replaces the current one
    unless it is infinite or NaN (``setYRot`` discards those), then ``setRot`` keeps ``% 360``.
    """
    kept = [F32(new) if math.isfinite(float(new)) else F32(old) for old, new in zip(current, loaded)]
    return mth.java_float_rem(kept[0], 360.0), mth.java_float_rem(kept[1], 360.0)


def teleport_rotation(yaw, pitch) -> tuple[np.float32, np.float32]:
    """Rotation stored by ``tp``: ``wrapDegrees`` on both, then pitch clamped to [-90, 90]."""
    return mth.wrap_degrees_f(yaw), mth.clamp_f(mth.wrap_degrees_f(pitch), -90.0, 90.0)
