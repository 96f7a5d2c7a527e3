"""Item frames hang on a block face: where one sits and what it saves (ItemFrame, HangingEntity,
BlockAttachedEntity; decompiled 26.1.2).

- ``settle(entity, version)``: a frame as ``summon`` leaves it (SummonCommand: the NBT loaded, then
  snapTo the position): its block is the position's (BlockAttachedEntity.setPos), its facing the
  NBT's ``Facing`` (down without one: ItemFrame.readAdditionalSaveData), its centre that block's
  less 0.46875 along the facing (ItemFrame.createBoundingBox via HangingEntity.recalculateBoundingBox),
  its rotation the facing's (ItemFrame.setDirection: yaw 90 x the 2D value, or pitch -90 x the step
  for up and down), and the fields it saves at their defaults (``ItemRotation`` 0, ``ItemDropChance``
  1, ``Invisible`` and ``Fixed`` false, the block as its release saves it).
- ``rehang(entity, block, version)``: a frame after its NBT is loaded again (``data``): its block the
  one its NBT names, if within 16 blocks of its ``Pos`` (else ``block``, the one it had:
  BlockAttachedEntity.readAdditionalSaveData), its centre and rotation its ``Facing``'s
  (ItemFrame.setDirection): so a changed ``Facing`` turns it, and a changed ``Pos`` alone moves
  nothing.
- ``box(centre, face)``: its bounding box; ``block_of(entity)``: the block it hangs in.
- ``survives(state, block, face, dimension, fixed, itself)``: ItemFrame.survives: a fixed frame
  always; else no collision in its box (the blocks: an entity's hard collision, a boat's or a
  shulker's, is not looked at), a solid block behind it (or, facing sideways, a repeater or
  comparator: DiodeBlock.isDiode) and no other frame's box meeting its own (a painting near it is
  not modelled).
"""
from __future__ import annotations

import math

import numpy as np

from emulator.world import block_shapes
from emulator.world.entity_types import saved_attached_block, set_attached_block
from emulator.world.errors import Unmodelled
from emulator.world.placed_states import OFFSETS
from mcfunction_parser.nbt import Byte, Float

FRAMES = frozenset({"minecraft:item_frame", "minecraft:glow_item_frame"})
FACE_DATA = {"down": 0, "up": 1, "north": 2, "south": 3, "west": 4, "east": 5}  # Direction.get3DDataValue
FACES = {v: k for k, v in FACE_DATA.items()}
YAW = {"south": 0.0, "west": 90.0, "north": 180.0, "east": 270.0}  # Direction.toYRot (2D data value x 90)
FRAME_DEPTH = 0.46875  # ItemFrame.createBoundingBox: the centre's offset back from the block's centre
DIODES = frozenset({"minecraft:repeater", "minecraft:comparator"})


def centre(block, face: str) -> tuple[float, float, float]:
    """Vec3.atCenterOf(block).relative(face, -0.46875)."""
    return tuple(c + 0.5 - FRAME_DEPTH * d for c, d in zip(block, OFFSETS[face]))


def rotation(face: str) -> tuple[float, float]:
    """ItemFrame.setDirection: (yaw, pitch)."""
    return (0.0, -90.0 * OFFSETS[face][1]) if OFFSETS[face][1] else (YAW[face], 0.0)


def face_of(entity) -> str:
    return FACES.get(int(entity.data.get("Facing", Byte(0))), "down")


def settle(entity, version) -> None:
    face = face_of(entity)
    block = tuple(math.floor(c) for c in entity.pos)
    entity.pos = centre(block, face)
    yaw, pitch = rotation(face)
    entity.yaw, entity.pitch = np.float32(yaw), np.float32(pitch)
    data = entity.data
    set_attached_block(data, block, version)
    data["Facing"] = Byte(FACE_DATA[face])
    data.setdefault("ItemRotation", Byte(0))
    data.setdefault("ItemDropChance", Float(1.0))
    data.setdefault("Invisible", Byte(0))
    data.setdefault("Fixed", Byte(0))


def rehang(entity, block, version) -> None:
    saved = saved_attached_block(entity.data, version)
    here = tuple(math.floor(c) for c in entity.pos)
    if saved is not None and sum((a - b) ** 2 for a, b in zip(saved, here)) < 16 ** 2:  # BlockPos.closerThan
        block = saved
    entity.pos = tuple(float(c) for c in block)  # settle hangs it on the block it is in
    settle(entity, version)


def block_of(entity) -> tuple[int, int, int]:
    """The block a frame hangs in: its centre less the offset, back along its facing."""
    return tuple(math.floor(c + FRAME_DEPTH * d) for c, d in zip(entity.pos, OFFSETS[face_of(entity)]))


def box(centre, face: str):
    """ItemFrame.calculateBoundingBox: 0.75 square, 0.0625 thick along the face's axis."""
    axis = [abs(d) for d in OFFSETS[face]].index(1)
    size = [0.75, 0.75, 0.75]
    size[axis] = 0.0625
    return tuple(c - s / 2 for c, s in zip(centre, size)) + tuple(c + s / 2 for c, s in zip(centre, size))


def survives(state, block, face: str, dimension: str, fixed: bool = False, itself=None) -> bool:
    if fixed:
        return True
    blocks = state.blocks_in(dimension)
    if block_shapes.collides(blocks.get(block)):
        return False
    dx, dy, dz = OFFSETS[face]
    behind = blocks.get((block[0] - dx, block[1] - dy, block[2] - dz))
    if not ((dy == 0 and behind.id in DIODES) or block_shapes.is_solid(behind)):
        return False
    return not _meets_a_hanging_entity(state, dimension, box(centre(block, face), face), itself)


def _meets_a_hanging_entity(state, dimension: str, area, itself) -> bool:
    """Level.getEntities(frame, box, HANGING_ENTITY): another frame whose box meets ``area``."""
    for entity in state.entities.entities:
        if entity is itself or not entity.alive or entity.dimension != dimension:
            continue
        if entity.type == "minecraft:painting" and all(abs(a - b) < 4 for a, b in zip(entity.pos, area[:3])):
            raise Unmodelled("an item frame beside a painting (whether their boxes meet)")
        if entity.type in FRAMES:
            other = box(entity.pos, face_of(entity))
            if all(area[i] < other[i + 3] and area[i + 3] > other[i] for i in range(3)):
                return True
    return False
