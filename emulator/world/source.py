"""The execution context (the game's ``CommandSourceStack``) as far as positions and rotations go.

``Source(pos, yaw, pitch, entity, anchor, dimension)``: position (3 doubles), rotation (float32 yaw,
pitch), the executing entity (``@s``, or None for the server), the anchor (``"feet"`` or ``"eyes"``)
and the level (a dimension id).

Methods (each returns a new Source or a position; the Source itself is immutable)
- ``anchor_position()``: ``Anchor.apply(source)``: the position, raised by the executor's eye
  height when anchored at eyes (no executor: the position as is).
- ``position_of(vec3)``: a position argument (``Vec3Argument`` with centre correction: absolute
  integer x/z get +0.5) resolved here: ``~`` against the position, ``^`` from the anchor position.
- ``rotation_of(vec2)``: a rotation argument resolved against this rotation.
- ``facing_position(target)``: ``execute facing X Y Z`` (from the anchor position).
- ``facing_entity(entity, anchor)``: ``execute facing entity E feet|eyes``.
- ``positioned(vec3)``: ``execute positioned X Y Z``: the resolved position, and the anchor goes
  back to feet (``positioned as``, ``at`` and ``facing`` keep the anchor).
- ``with_position / with_rotation / with_entity / with_anchor``: ``positioned as``, ``rotated``,
  ``as``, ``anchored``. ``at(entity)``: ``execute at`` (position and rotation of the entity).
- ``aligned(axes)``: ``execute align xyz`` (``Vec3.align``: floor of the named axes).

Sources (decompiled 1.21): commands/CommandSourceStack.java, commands/arguments/EntityAnchorArgument.java,
commands/arguments/coordinates/WorldCoordinate(s).java, LocalCoordinates.java, Vec3Argument.java.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from mcfunction_parser import ast
from emulator.world import rotation

F32 = np.float32


def world_coordinate(coord: ast.Coord, base: float, centre: bool) -> float:
    """``WorldCoordinate.get``: ``~v`` adds the base; an absolute integer literal is centred (+0.5)
    where the argument asks for it (x and z of entity positions)."""
    if coord.kind == "rel":
        return coord.value + base
    return coord.value + 0.5 if centre and coord.is_int else coord.value


@dataclass(frozen=True)
class Source:
    pos: tuple[float, float, float] = (0.0, 0.0, 0.0)
    yaw: np.float32 = F32(0.0)
    pitch: np.float32 = F32(0.0)
    entity: object = None  # emulator.world.entities.Entity or None
    anchor: str = "feet"
    dimension: str = "minecraft:overworld"

    def anchor_position(self) -> tuple[float, float, float]:
        if self.entity is None or self.anchor != "eyes":
            return self.pos
        x, y, z = self.pos
        return (x, y + float(self.entity.eye_height), z)

    def position_of(self, vec: ast.Vec3, centre: bool = True) -> tuple[float, float, float]:
        if vec.is_local:
            return rotation.local_to_world(self.anchor_position(), self.yaw, self.pitch,
                                           vec.x.value, vec.y.value, vec.z.value)
        x, y, z = self.pos
        return (world_coordinate(vec.x, x, centre), world_coordinate(vec.y, y, False),
                world_coordinate(vec.z, z, centre))

    def rotation_of(self, vec: ast.Vec2) -> tuple[np.float32, np.float32]:
        return rotation.relative_rotation(self.yaw, self.pitch, vec.x, vec.y)

    def facing_position(self, target) -> "Source":
        yaw, pitch = rotation.facing_rotation(self.anchor_position(), target)
        return replace(self, yaw=yaw, pitch=pitch)

    def facing_entity(self, entity, anchor: str) -> "Source":
        return self.facing_position(entity.anchor(anchor))

    def positioned(self, vec: ast.Vec3) -> "Source":
        return replace(self, pos=self.position_of(vec), anchor="feet")

    def with_position(self, pos) -> "Source":
        return replace(self, pos=tuple(float(v) for v in pos))

    def with_rotation(self, yaw, pitch) -> "Source":
        return replace(self, yaw=F32(yaw), pitch=F32(pitch))

    def with_entity(self, entity) -> "Source":
        return replace(self, entity=entity)

    def with_anchor(self, anchor: str) -> "Source":
        return replace(self, anchor=anchor)

    def aligned(self, axes: str) -> "Source":
        return replace(self, pos=tuple(float(math.floor(v)) if a in axes else v for a, v in zip("xyz", self.pos)))

    def at(self, entity) -> "Source":
        return replace(self, pos=entity.pos, yaw=entity.yaw, pitch=entity.pitch)
