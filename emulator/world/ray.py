"""Segments through the world: the blocks a segment crosses and where it enters a box or a block.

- ``cells(start, end)``: BlockGetter.traverseBlocks, the block cells from ``start`` to ``end`` in
  the order the game visits them (its ends pulled 1e-7 of the segment back and forth).
- ``clip(box, start, end)``: AABB.clip, where the segment enters ``box`` (None when it does not;
  a start inside the box enters nothing).
- ``clip_blocks(blocks, start, end)``: BlockGetter.clip with the blocks' collision shapes and no
  fluids (ClipContext.Block.COLLIDER, Fluid.NONE): ``(location, cell)`` of the first block hit, or
  None. The shapes known are full cubes and empty ones (:mod:`emulator.world.block_shapes`);
  another shape on the way raises Unmodelled.
- ``box_cells(box)``: the block cells a box touches; ``boxes_meet(a, b)``: AABB.intersects.

Sources (decompiled 1.21): world/level/BlockGetter.java (clip, traverseBlocks), world/phys/AABB.java
(clip, getDirection, clipPoint), world/phys/shapes/VoxelShape.java (clip: a start just inside the
shape hits at once), util/Mth.java (lerp, frac, sign, floor).
"""
from __future__ import annotations

import math

from emulator.world import block_shapes

_EPSILON = 1.0E-7
_MAX = 1.7976931348623157e308  # Double.MAX_VALUE


def _lerp(delta: float, start: float, end: float) -> float:
    return start + delta * (end - start)


def _frac(x: float) -> float:
    return x - math.floor(x)


def _sign(x: float) -> int:
    return 0 if x == 0.0 else 1 if x > 0.0 else -1


def cells(start, end):
    """BlockGetter.traverseBlocks: the first cell, then each cell the segment steps into."""
    if tuple(start) == tuple(end):
        return
    far = [_lerp(-_EPSILON, e, s) for s, e in zip(start, end)]
    near = [_lerp(-_EPSILON, s, e) for s, e in zip(start, end)]
    cell = [math.floor(c) for c in near]
    yield tuple(cell)
    delta = [f - n for f, n in zip(far, near)]
    step = [_sign(d) for d in delta]
    t_delta = [_MAX if s == 0 else s / d for s, d in zip(step, delta)]
    t_next = [t * (1.0 - _frac(n) if s > 0 else _frac(n)) for t, s, n in zip(t_delta, step, near)]
    while t_next[0] <= 1.0 or t_next[1] <= 1.0 or t_next[2] <= 1.0:
        if t_next[0] < t_next[1]:
            axis = 0 if t_next[0] < t_next[2] else 2
        else:
            axis = 1 if t_next[1] < t_next[2] else 2
        cell[axis] += step[axis]
        t_next[axis] += t_delta[axis]
        yield tuple(cell)


def clip(box, start, end):
    """AABB.clip: where the segment ``start``-``end`` enters ``box`` (a face crossed at 0 < t < 1,
    the faces tried x, then y, then z), None when it does not."""
    delta = tuple(b - a for a, b in zip(start, end))
    t_best = 1.0
    hit = None
    for axis in range(3):
        d = delta[axis]
        if d > _EPSILON:
            face = box[axis]
        elif d < -_EPSILON:
            face = box[axis + 3]
        else:
            continue
        t = (face - start[axis]) / d
        if not 0.0 < t < t_best:
            continue
        if all(box[i] - _EPSILON < start[i] + t * delta[i] < box[i + 3] + _EPSILON for i in range(3) if i != axis):
            t_best, hit = t, True
    if hit is None:
        return None
    return tuple(s + t_best * d for s, d in zip(start, delta))


def clip_blocks(blocks, start, end):
    """The first block with a collision shape the segment meets: ``(location, cell)``, or None."""
    for cell in cells(start, end):
        block = blocks.get(cell)
        if block.is_air or not block_shapes.collides(block):
            continue
        location = _clip_cube(cell, start, end)
        if location is not None:
            return location, cell
    return None


def _clip_cube(cell, start, end):
    """VoxelShape.clip for a full cube at ``cell``: a start that, moved a thousandth of the way,
    is inside hits there; else where the segment enters the cube."""
    delta = tuple(e - s for s, e in zip(start, end))
    if delta[0] * delta[0] + delta[1] * delta[1] + delta[2] * delta[2] < _EPSILON:
        return None
    inside = tuple(s + d * 0.001 for s, d in zip(start, delta))
    if all(0.0 <= p - c < 1.0 for p, c in zip(inside, cell)):
        return inside
    return clip((*cell, *(c + 1 for c in cell)), start, end)


def box_cells(box):
    """The block cells a box ``(x0, y0, z0, x1, y1, z1)`` touches, its faces included."""
    lo = [math.floor(c) for c in box[:3]]
    hi = [math.floor(c) for c in box[3:]]
    for x in range(lo[0], hi[0] + 1):
        for y in range(lo[1], hi[1] + 1):
            for z in range(lo[2], hi[2] + 1):
                yield (x, y, z)


def boxes_meet(a, b) -> bool:
    """AABB.intersects: the boxes overlap (touching faces do not)."""
    return all(a[i] < b[i + 3] and a[i + 3] > b[i] for i in range(3))
