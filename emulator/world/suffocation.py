"""Living entities whose eyes are inside a block: ``in_wall`` damage, 1 each tick (the hurt's
invulnerable time lets one in 10 through), as LivingEntity.baseTick deals it before the air.

- ``tick_in_wall(state, hurt)``: every living entity in a wall hurt by ``hurt(state, entity, amount,
  source)`` (:func:`emulator.world.combat.hurt`); ``tick_entity(state, entity, hurt)``: one
  entity's; ``tick_is_idle(state)``: none is.
- ``in_wall(state, entity) -> bool``: Entity.isInWall.

Entity.isInWall: not for a spectator (noPhysics); a box 0.8 x the entity's width wide and 1.0E-6
high around its eyes meets a block that is not air, suffocates (BlockBehaviour.Properties.
isSuffocating: by default a full collision cube; never glass, stained or tinted glass, leaves,
copper grates, mangrove roots, a moving piston, an open shulker box or an extended piston; always
farmland, dirt paths, soul sand and mud) and whose collision shape that box meets. A block whose
shape is not known here (slabs, stairs ...) is reported as not modelled. An armor stand takes no
``in_wall`` hurt (ArmorStand.hurtServer: the damage cannot break it): it is left out.

Sources (decompiled 26.1.2 and 1.21.3): world/entity/Entity.java (isInWall),
world/entity/LivingEntity.java (baseTick), world/level/block/Blocks.java (isSuffocating),
world/level/block/{Farm,DirtPath,SoulSand,Mud}Block.java (their collision shapes' tops).
"""
from __future__ import annotations

import math

import numpy as np

from emulator.world import block_shapes, living
from emulator.world.errors import Unmodelled
from emulator.world.loot_context import DamageSource

DAMAGE = 1.0
EYE_BOX_HEIGHT = 1.0E-6
WIDTH_PART = np.float32(0.8)
_NEVER = frozenset("minecraft:" + n for n in (
    "glass tinted_glass mangrove_roots moving_piston").split())
_NEVER_SUFFIXES = ("_stained_glass", "_leaves", "copper_grate")
# isSuffocating(always) with a collision shape lower than the block: its top, in blocks
_ALWAYS_TOPS = {"minecraft:farmland": 15 / 16, "minecraft:dirt_path": 15 / 16, "minecraft:soul_sand": 14 / 16,
                "minecraft:mud": 14 / 16}
NOT_HURT = frozenset({"minecraft:armor_stand"})


def tick_is_idle(state) -> bool:
    return not any(_may_be_walled(state, e) for e in state.entities.living_mobs())


def _may_be_walled(state, entity) -> bool:
    try:
        return _walled(state, entity)
    except Unmodelled:
        return True  # the tick reports it


def tick_in_wall(state, hurt) -> None:
    for entity in list(state.entities.living_mobs()):
        tick_entity(state, entity, hurt)


def tick_entity(state, entity, hurt) -> None:
    """One living entity's wall check (the world step's body, for a caller looping over them already)."""
    try:
        if _walled(state, entity) and living.health(entity) > 0:
            hurt(state, entity, DAMAGE, DamageSource("minecraft:in_wall"))
    except Unmodelled as reason:
        state.unmodelled_once("a mob's eyes in a block", reason)


def _walled(state, entity) -> bool:
    return entity.alive and entity.type not in NOT_HURT and in_wall(state, entity)


def in_wall(state, entity) -> bool:
    if entity.is_player and entity.gamemode == "spectator":
        return False
    blocks = state.blocks_in(entity.dimension)
    if not blocks.states:  # no block at all: nothing to be in
        return False
    half = _half_width(entity.box_extent()[0])
    x, y, z = entity.pos
    eye = y + float(entity.eye_height)
    box = (x - half, eye - EYE_BOX_HEIGHT / 2, z - half, x + half, eye + EYE_BOX_HEIGHT / 2, z + half)
    states = blocks.states
    for cx in range(math.floor(box[0]), math.floor(box[3]) + 1):
        for cy in range(math.floor(box[1]), math.floor(box[4]) + 1):
            for cz in range(math.floor(box[2]), math.floor(box[5]) + 1):
                block = states.get((cx, cy, cz))  # none: air
                if block is not None and _suffocates(block, (cx, cy, cz), box):
                    return True
    return False


_HALVES: dict[float, float] = {}


def _half_width(half_extent: float) -> float:
    """Half of width x 0.8F (Entity.isInWall: the float product, widened), for a half width."""
    found = _HALVES.get(half_extent)
    if found is None:
        found = _HALVES[half_extent] = float(np.float32(half_extent * 2) * WIDTH_PART) / 2.0
    return found


def _suffocates(block, cell, box) -> bool:
    """isSuffocating and the collision shape meeting ``box`` (an open overlap: Shapes.joinIsNotEmpty)."""
    if block.is_air or block.id in _NEVER or block.id.endswith(_NEVER_SUFFIXES):
        return False
    top = _ALWAYS_TOPS.get(block.id)
    if top is None:
        if block.id.endswith("shulker_box") or block.id in ("minecraft:piston", "minecraft:sticky_piston"):
            raise Unmodelled(f"whether {block.id} suffocates (open or extended)")
        if not block_shapes.is_collision_full(block):
            return False
        top = 1.0
    cx, cy, cz = cell
    return (box[0] < cx + 1 and box[3] > cx and box[1] < cy + top and box[4] > cy
            and box[2] < cz + 1 and box[5] > cz)
