"""Item frames hang on a block face: where one sits and what it saves (ItemFrame, HangingEntity,
BlockAttachedEntity; decompiled 26.1.2).

- ``settle(entity, version)``: a frame as ``summon`` leaves it (SummonCommand: the NBT loaded, then
  snapTo the position): its block is the position's (BlockAttachedEntity.setPos), its facing the
  NBT's ``Facing`` (down without one: ItemFrame.readAdditionalSaveData), its centre that block's
  less 0.46875 along the facing (ItemFrame.createBoundingBox via HangingEntity.recalculateBoundingBox),
  its rotation the facing's (ItemFrame.setDirection: yaw 90 x the 2D value, or pitch -90 x the step
  for up and down), and the fields it saves at their defaults (``ItemRotation`` 0, ``ItemDropChance``
  1, ``Invisible`` and ``Fixed`` false, the block as its release saves it).
"""
from __future__ import annotations

import math

import numpy as np

from emulator.world.entity_types import set_attached_block
from emulator.world.placed_states import OFFSETS
from mcfunction_parser.nbt import Byte, Float

FRAMES = frozenset({"minecraft:item_frame", "minecraft:glow_item_frame"})
FACE_DATA = {"down": 0, "up": 1, "north": 2, "south": 3, "west": 4, "east": 5}  # Direction.get3DDataValue
FACES = {v: k for k, v in FACE_DATA.items()}
YAW = {"south": 0.0, "west": 90.0, "north": 180.0, "east": 270.0}  # Direction.toYRot (2D data value x 90)
FRAME_DEPTH = 0.46875  # ItemFrame.createBoundingBox: the centre's offset back from the block's centre


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
