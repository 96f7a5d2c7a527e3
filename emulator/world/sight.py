"""What a player looks at: the ``looking_at`` field of the player predicate.

- ``looked_at(state, player)``: the entity PlayerPredicate.matches tests, or None.

Sources (decompiled 1.21): advancements/critereon/PlayerPredicate.java (matches: from the eyes,
100 blocks along the view vector), world/entity/projectile/ProjectileUtil.java
(getEntityHitResult: the nearest entity whose box the segment enters), world/phys/AABB.java
(clip, getDirection, clipPoint), world/entity/LivingEntity.java (hasLineOfSight: from eye to eye,
at most 128 blocks, no block collider between).
"""
from __future__ import annotations

import math

from emulator.world import rotation
from emulator.world.errors import Unmodelled

REACH = 100.0
SIGHT = 128.0
_EPSILON = 1.0E-7


def looked_at(state, player):
    """The nearest entity (not the player, not a spectator) whose bounding box the segment from
    the player's eyes 100 blocks along its view enters first; None when there is none or the
    player cannot see it. A line of sight that crosses a block is not modelled (the blocks'
    collision shapes are not known here)."""
    x, y, z = player.pos
    eye = (x, y + float(player.eye_height), z)
    view = rotation.view_vector(player.yaw, player.pitch)
    end = tuple(e + v * REACH for e, v in zip(eye, view))
    search = _inflate((*map(min, eye, end), *map(max, eye, end)), 1.0)
    best, nearest = None, math.inf
    for entity in state.entities.entities:
        if (entity is player or not entity.alive or getattr(entity, "gamemode", None) == "spectator"
                or getattr(entity, "dimension", None) != getattr(player, "dimension", None)):
            continue
        box = entity.bounding_box
        if not _intersects(box, search):
            continue
        hit = clip(box, eye, end)
        if hit is not None:
            distance = sum((h - e) ** 2 for h, e in zip(hit, eye))
            if distance < nearest:
                best, nearest = entity, distance
    if best is None or not _line_of_sight(state, player, eye, best):
        return None
    return best


def clip(box, start, end):
    """AABB.clip: where the segment ``start``-``end`` enters ``box`` (a face crossed at 0 < t < 1),
    None when it does not (a start inside the box enters nothing)."""
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
        point = tuple(start[i] + t * delta[i] for i in range(3))
        if all(box[i] - _EPSILON < point[i] < box[i + 3] + _EPSILON for i in range(3) if i != axis):
            t_best, hit = t, point
    return hit


def _line_of_sight(state, player, eye, target) -> bool:
    tx, ty, tz = target.pos
    goal = (tx, ty + float(target.eye_height), tz)
    if math.dist(eye, goal) > SIGHT:
        return False
    for cell in _cells(eye, goal):
        if not state.blocks.get(cell).is_air:
            raise Unmodelled("a player's line of sight past blocks (their collision shapes are not modelled)")
    return True


def _cells(start, end):
    """The block cells the segment passes through, in order (BlockGetter.traverseBlocks)."""
    cell = [math.floor(c) for c in start]
    last = [math.floor(c) for c in end]
    delta = [b - a for a, b in zip(start, end)]
    step = [(d > 0) - (d < 0) for d in delta]
    t_max = [((cell[i] + (step[i] > 0)) - start[i]) / delta[i] if step[i] else math.inf for i in range(3)]
    t_delta = [abs(1.0 / delta[i]) if step[i] else math.inf for i in range(3)]
    yield tuple(cell)
    for _ in range(sum(abs(a - b) for a, b in zip(cell, last))):
        axis = min(range(3), key=t_max.__getitem__)
        cell[axis] += step[axis]
        t_max[axis] += t_delta[axis]
        yield tuple(cell)


def _intersects(a, b) -> bool:
    return all(a[i] < b[i + 3] and a[i + 3] > b[i] for i in range(3))


def _inflate(box, amount: float):
    return (*(c - amount for c in box[:3]), *(c + amount for c in box[3:]))
