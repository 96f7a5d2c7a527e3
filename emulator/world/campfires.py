"""A campfire's smoke over the column above it, as a location predicate's ``smokey`` reads it.

- ``is_smokey_pos(blocks, pos, resources)``: CampfireBlock.isSmokeyPos: looking down from ``pos``
  up to five blocks, a lit campfire makes it smokey; the first block whose collision shape meets
  a fence post through the column's centre (a full cube, a campfire) stops the smoke unless a
  lit campfire is right under it. A block whose shape the emulator does not keep (slabs,
  fences, stairs ...) is not modelled (:mod:`emulator.world.block_shapes`).

Sources (decompiled 1.21): world/level/block/CampfireBlock.java (isSmokeyPos, isLitCampfire,
VIRTUAL_FENCE_POST = box(6, 0, 6, 10, 16, 10), SHAPE = box(0, 0, 0, 16, 7, 16)),
data/tags/VanillaBlockTagsProvider.java (#campfires).
"""
from __future__ import annotations

from emulator.world import block_shapes

SMOKE_REACH = 5  # CampfireBlock.isSmokeyPos looks this many blocks down


def is_lit_campfire(state, resources) -> bool:
    """CampfireBlock.isLitCampfire: a block of #minecraft:campfires with ``lit=true``."""
    return dict(state.properties).get("lit") == "true" and resources.in_tag("block", "minecraft:campfires", state.id)


def _meets_fence_post(state, resources) -> bool:
    """Shapes.joinIsNotEmpty(VIRTUAL_FENCE_POST, the collision shape): a campfire's slab of a shape
    spans the whole block; other blocks as far as their shapes are known."""
    if state.id in ("minecraft:campfire", "minecraft:soul_campfire"):
        return True
    return block_shapes.collides(state)


def is_smokey_pos(blocks, pos, resources) -> bool:
    x, y, z = pos
    for depth in range(1, SMOKE_REACH + 1):
        below = blocks.get((x, y - depth, z))
        if is_lit_campfire(below, resources):
            return True
        if _meets_fence_post(below, resources):
            return is_lit_campfire(blocks.get((x, y - depth - 1, z)), resources)
    return False
