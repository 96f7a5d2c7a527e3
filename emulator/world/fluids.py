"""Water as entities feel it (Entity.updateFluidHeightAndDoFluidPushing): whether an entity's box
is in water, and whether that water would push it.

- ``in_water(blocks, box)``: the box (less 0.001 each side) meets a water cell whose fluid top is
  at or above the box's bottom (Entity.isInWater after baseTick).
- ``pushing(blocks, box)``: the cell of water meeting the box whose flow is not zero
  (FlowingFluid.getFlow), None when all of it is still; a pack's pools of sources are still.
- ``is_water(block)``: water, a bubble column or a waterlogged block.

Heights (FlowingFluid.getHeight): a cell under more water is full (1); else amount / 9, a source
or a falling flow 8, a flow of level n 8 - n. A source's flow (getFlow) is not zero beside a flow,
or beside a free cell over water (a fall), or when it falls: those cells are reported as pushing.

Sources (decompiled 1.21): world/entity/Entity.java (updateFluidHeightAndDoFluidPushing),
world/level/material/FlowingFluid.java (getHeight, getOwnHeight, getFlow).
"""
from __future__ import annotations

import math

_SOURCE_HEIGHT = 8.0 / 9.0
_MARGIN = 0.001
_SIDES = ((1, 0), (-1, 0), (0, 1), (0, -1))


def is_water(block) -> bool:
    return block.id in ("minecraft:water", "minecraft:bubble_column") or dict(block.properties).get(
        "waterlogged") == "true"


def _level(block) -> int:
    return int(dict(block.properties).get("level", "0")) if block.id == "minecraft:water" else 0


def height(blocks, cell):
    """FlowingFluid.getHeight of the water in the cell, None without water."""
    block = blocks.get(cell)
    if not is_water(block):
        return None
    x, y, z = cell
    if is_water(blocks.get((x, y + 1, z))):
        return 1.0
    level = _level(block)
    return _SOURCE_HEIGHT if level == 0 or level >= 8 else (8 - level) / 9.0


def _cells(box):
    """BlockPos.betweenClosed(floor(min), ceil(max) - 1) of the box less the margin."""
    lo = [math.floor(c + _MARGIN) for c in box[:3]]
    hi = [math.ceil(c - _MARGIN) - 1 for c in box[3:]]
    return [(x, y, z) for x in range(lo[0], hi[0] + 1) for y in range(lo[1], hi[1] + 1) for z in range(lo[2], hi[2] + 1)]


def _wet_cells(blocks, box):
    bottom = box[1] + _MARGIN
    for cell in _cells(box):
        top = height(blocks, cell)
        if top is not None and cell[1] + top >= bottom:
            yield cell


def in_water(blocks, box) -> bool:
    return any(True for _ in _wet_cells(blocks, box))


def pushing(blocks, box):
    for cell in _wet_cells(blocks, box):
        if _flows(blocks, cell):
            return cell
    return None


def _flows(blocks, cell) -> bool:
    """Whether FlowingFluid.getFlow may be other than zero: a flow or falling water, or a source
    beside a flow or beside a free cell over water."""
    if _level(blocks.get(cell)) != 0:
        return True
    x, y, z = cell
    for dx, dz in _SIDES:
        side = blocks.get((x + dx, y, z + dz))
        if is_water(side):
            if _level(side) != 0:
                return True
        elif side.is_air and is_water(blocks.get((x + dx, y - 1, z + dz))):
            return True
    return False
