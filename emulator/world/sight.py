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

from emulator.world import ray, rotation
from emulator.world.errors import Unmodelled

REACH = 100.0
SIGHT = 128.0


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
        hit = ray.clip(box, eye, end)
        if hit is not None:
            distance = sum((h - e) ** 2 for h, e in zip(hit, eye))
            if distance < nearest:
                best, nearest = entity, distance
    if best is None or not _line_of_sight(state, player, eye, best):
        return None
    return best


def _line_of_sight(state, player, eye, target) -> bool:
    tx, ty, tz = target.pos
    goal = (tx, ty + float(target.eye_height), tz)
    if math.dist(eye, goal) > SIGHT:
        return False
    for cell in ray.cells(eye, goal):
        if not state.blocks.get(cell).is_air:
            raise Unmodelled("a player's line of sight past blocks (their collision shapes are not modelled)")
    return True


def _intersects(a, b) -> bool:
    return all(a[i] < b[i + 3] and a[i + 3] > b[i] for i in range(3))


def _inflate(box, amount: float):
    return (*(c - amount for c in box[:3]), *(c + amount for c in box[3:]))
