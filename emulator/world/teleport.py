"""``tp``/``teleport``: where each form puts its targets, with the game's float math.

Public functions (each returns a ``Destination(pos, yaw, pitch)`` per target, computed against the
entity's state at that moment, and ``apply`` moves the entity there)
- ``to_position(source, entity, location, rotation_arg=None, facing=None, facing_entity=None,
  facing_anchor="feet")``: ``tp TARGETS POS [ROT | facing POS | facing entity E [ANCHOR]]``.
  Without a rotation the entity keeps its own (wrapped); ``~`` in a rotation is relative to the
  *execution* rotation, not the entity's. ``facing`` turns the moved entity from its own anchor
  (the execution anchor applied to it) towards the target.
- ``to_position_self(source, location)``: ``tp POS``: the executor, rotation "~ ~" (the execution
  rotation).
- ``to_entity(destination)``: ``tp [TARGETS] DEST``: the destination entity's position and rotation.
- ``apply(entity, destination, store=None)``: set pos and rotation, zero the vertical motion (``tp``
  does); with the ``store``, move the entity to the destination's level (the source's level for a
  position, the destination entity's for an entity: ``execute in the_nether run tp @s ~ ~ ~``
  crosses, and so does ``execute as @e run tp @s ~ ~ ~`` for an entity outside the server's
  overworld). Between levels the entity comes last in its new level's order; the game makes a new
  entity object there (Entity.teleportCrossDimension), the emulator keeps the one, so a context
  still running as the old one (``@s``) sees the moved entity. An entity crossing levels leaves its
  vehicle; from 1.21.2 its passengers go along (their offsets and turns kept) and ride it again,
  before they stay behind (``version``: the packs' release).
- ``teleport(source, targets, ..., store=None, version=None)``: the whole command over several targets, in order
  (each target sees the earlier ones already moved); returns the count.
Every rotation goes through ``wrapDegrees`` and the pitch is clamped to [-90, 90]; a destination
outside x/z [-30000000, 30000000) or y [-20000000, 20000000) fails "Invalid position for teleport".

Source: decompiled 1.21 server/commands/TeleportCommand.java (teleportToPos, teleportToEntity,
performTeleport, LookAtPosition/LookAtEntity) and world/entity/Entity.java (teleportTo, moveTo, lookAt).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from mcfunction_parser import ast
from emulator.world import rotation
from emulator.world.dimensions import OVERWORLD
from emulator.world.entities import in_spawnable_bounds
from emulator.world.errors import CommandFailure
from emulator.world.relations import start_riding, stop_riding
from emulator.world.source import Source

PASSENGERS_TRAVEL_VERSION = (1, 21, 2)  # Entity.teleportCrossDimension takes the passengers along


@dataclass(frozen=True)
class Destination:
    pos: tuple[float, float, float]
    yaw: np.float32
    pitch: np.float32
    dimension: str = OVERWORLD


def _moved(pos, yaw, pitch, dimension: str) -> Destination:
    if not in_spawnable_bounds(pos):
        raise CommandFailure("commands.teleport.invalidPosition")
    yaw, pitch = rotation.teleport_rotation(yaw, pitch)
    return Destination(tuple(pos), yaw, pitch, dimension)


def look_at(source: Source, pos, entity, target) -> tuple[np.float32, np.float32]:
    """``Entity.lookAt(source anchor, target)`` (LookAt.perform): from the entity's anchor at ``pos``
    (``tp`` turns it after the move, ``rotate`` where it stands)."""
    x, y, z = pos
    origin = (x, y + float(entity.eye_height), z) if source.anchor == "eyes" else (x, y, z)
    return rotation.facing_rotation(origin, target)


def to_position(source: Source, entity, location: ast.Vec3, rotation_arg: ast.Vec2 | None = None,
                facing: ast.Vec3 | None = None, facing_entity=None, facing_anchor: str = "feet") -> Destination:
    pos = source.position_of(location)
    yaw, pitch = source.rotation_of(rotation_arg) if rotation_arg is not None else (entity.yaw, entity.pitch)
    moved = _moved(pos, yaw, pitch, source.dimension)
    target = None
    if facing is not None:
        target = source.position_of(facing)
    elif facing_entity is not None:
        target = facing_entity.anchor(facing_anchor)
    if target is None:
        return moved
    yaw, pitch = look_at(source, moved.pos, entity, target)
    return Destination(moved.pos, yaw, pitch, moved.dimension)


def to_position_self(source: Source, location: ast.Vec3) -> Destination:
    """``tp POS``: teleportToPos with ``WorldCoordinates.current()`` as the rotation."""
    return _moved(source.position_of(location), source.yaw, source.pitch, source.dimension)


def to_entity(destination) -> Destination:
    return _moved(destination.pos, destination.yaw, destination.pitch, destination.dimension)


def apply(entity, destination: Destination, store=None, version=None) -> None:
    """Move the entity; a non-finite rotation is discarded (``setYRot``/``setXRot`` refuse it)."""
    if store is not None and destination.dimension != entity.dimension and entity.alive:  # a killed one stays
        _cross_levels(entity, destination, store, version)
        return
    _move(entity, destination)


def _cross_levels(entity, destination: Destination, store, version) -> None:
    """A teleport into another level. From 1.21.2 (Entity.teleport -> teleportCrossDimension) the
    entity leaves its vehicle and takes its passengers along: each keeps its offset from it and its
    turn relative to it (calculatePassengerTransition) and rides it again; before
    (Entity.teleportTo -> unRide) it leaves its vehicle and its passengers stay behind."""
    stop_riding(entity)
    riders = list(entity.passengers)
    for rider in riders:
        stop_riding(rider)
    old_pos, old_yaw, old_pitch = entity.pos, entity.yaw, entity.pitch
    store.move_to_level(entity, destination.dimension)
    _move(entity, destination)
    if version is None or tuple(version) < PASSENGERS_TRAVEL_VERSION:
        return
    for rider in riders:
        pos = tuple(d + (r - o) for d, r, o in zip(destination.pos, rider.pos, old_pos))
        yaw = destination.yaw + (float(rider.yaw) - float(old_yaw))
        pitch = destination.pitch + (float(rider.pitch) - float(old_pitch))
        _cross_levels(rider, Destination(pos, yaw, pitch, destination.dimension), store, version)
        start_riding(rider, entity)


def set_rotation(entity, yaw, pitch) -> None:
    """Entity.setYRot/setXRot: a non-finite angle is discarded, any other kept as given."""
    if math.isfinite(yaw):
        entity.yaw = np.float32(yaw)
    if math.isfinite(pitch):
        entity.pitch = np.float32(pitch)


def _move(entity, destination: Destination) -> None:
    entity.pos = destination.pos
    set_rotation(entity, destination.yaw, destination.pitch)
    vx, _, vz = entity.motion
    entity.motion = (vx, 0.0, vz)  # deltaMovement.multiply(1, 0, 1)


def teleport(source: Source, targets: list, location: ast.Vec3 | None = None, destination_entity=None,
             rotation_arg: ast.Vec2 | None = None, facing: ast.Vec3 | None = None,
             facing_entity=None, facing_anchor: str = "feet", store=None, version=None) -> int:
    """The whole ``tp TARGETS ...`` command; returns how many entities were teleported."""
    for entity in targets:
        if destination_entity is not None:
            dest = to_entity(destination_entity)
        else:
            dest = to_position(source, entity, location, rotation_arg, facing, facing_entity, facing_anchor)
        apply(entity, dest, store, version)
    return len(targets)
