"""A chorus fruit's random teleport (TeleportRandomlyConsumeEffect from 1.21.2, ChorusFruitItem.
finishUsingItem before): up to 16 tries at a random spot within the diameter (16) round the
eater, each dropped to the first block below that blocks motion (LivingEntity.randomTeleport),
taken when the eater's box there is free of blocks and liquids. The eater leaves its vehicle.

- ``teleport_randomly(state, entity, diameter=16.0) -> bool``: whether it moved.

The tries draw from the emulator's seeded random, not the entity's own: where the eater lands
differs from the game, the rules it lands by do not. Which blocks block motion and collide is
known for full cubes and blocks without collision (emulator.world.block_shapes); another block
met on the way raises Unmodelled. Entities that collide like blocks (boats, shulkers) are not
counted.

Sources (decompiled 1.21.x and 26.1): world/item/consume_effects/TeleportRandomlyConsumeEffect.java,
world/item/ChorusFruitItem.java, world/entity/LivingEntity.java (randomTeleport),
world/level/block/state/BlockBehaviour.java (blocksMotion: solid, not a cobweb).
"""
from __future__ import annotations

import math

from emulator.world import block_shapes
from emulator.world.errors import Unmodelled
from emulator.world.relations import stop_riding

# a level's lowest y and logical height (its dimension type's min_y and logical_height)
_LOGICAL = {"minecraft:overworld": (-64, 384), "minecraft:the_nether": (0, 128), "minecraft:the_end": (0, 256)}
_LIQUIDS = ("minecraft:water", "minecraft:lava")


def teleport_randomly(state, entity, diameter: float = 16.0) -> bool:
    if entity.dimension not in _LOGICAL:
        raise Unmodelled(f"a random teleport in {entity.dimension} (its dimension type's heights)")
    low, height = _LOGICAL[entity.dimension]
    random = state.resources.random
    for _ in range(16):
        x = entity.pos[0] + (random.random() - 0.5) * diameter
        y = min(max(entity.pos[1] + (random.randrange(int(diameter)) - int(diameter / 2)), low), low + height - 1)
        z = entity.pos[2] + (random.random() - 0.5) * diameter
        stop_riding(entity)
        if _random_teleport(state, entity, x, y, z, low):
            return True
    return False


def _random_teleport(state, entity, x: float, y: float, z: float, low: int) -> bool:
    """LivingEntity.randomTeleport: down to the first block that blocks motion, then free of
    collisions and liquids."""
    blocks = state.blocks_in(entity.dimension)
    bx, by, bz = math.floor(x), math.floor(y), math.floor(z)
    while by > low:
        if block_shapes.is_solid(blocks.get((bx, by - 1, bz))):
            break
        y -= 1
        by -= 1
    else:
        return False
    before = entity.pos
    entity.pos = (x, y, z)
    if _free(blocks, entity.bounding_box):
        return True
    entity.pos = before
    return False


def _free(blocks, box) -> bool:
    """Level.noCollision (blocks only) and not containsAnyLiquid for the box."""
    x0, y0, z0, x1, y1, z1 = box
    for bx in range(math.floor(x0), math.ceil(x1)):
        for by in range(math.floor(y0), math.ceil(y1)):
            for bz in range(math.floor(z0), math.ceil(z1)):
                block = blocks.get((bx, by, bz))
                if block.id in _LIQUIDS or block_shapes.collides(block):
                    return False
    return True
