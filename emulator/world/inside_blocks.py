"""The blocks a player is inside in a tick: what fires the ``enter_block`` trigger
(ServerPlayer.onInsideBlock), block by block.

- ``entered(state, player, moved) -> list[BlockState]``: the blocks, in the game's order, for a player
  whose tick checks them; ``moved`` is its move this tick (``(from, to)``, None when it made none).
  Raises Unmodelled where the game's answer needs what is not modelled here.

Which players, and which blocks, by release:
- from 1.21.2, every living player that is no spectator, each tick (LivingEntity.aiStep ends in
  Entity.applyEffectsFromBlocks on the server; Player.tick sets noPhysics for a spectator, and
  Entity.isAffectedByBlocks is false then): the blocks that are not air in the cells of the player's
  box deflated by 1.0E-5 (BlockGetter.boxTraverseBlocks / forEachBlockIntersectedBetween: a move
  under 0.99999 blocks looks only at the box where it ends), x fastest, then y, then z
  (BlockPos.betweenClosed). A block whose inside shape is not the full cube (tripwire and the end
  portal; from 1.21.5 also cauldrons and powder snow, seen in 1.21.7: getEntityInsideCollisionShape)
  counts only when the box meets that shape, and a longer move looks at the blocks on its way:
  neither is modelled.
- before 1.21.2, a player's blocks are checked when it moves (Entity.move ends in
  tryCheckInsideBlocks): a PackTest dummy moves each tick (its travel), air included (checkInsideBlocks
  has no air test then), the cells of its box shrunk by 1.0E-7 (0.001 before 1.19.3), x, then y,
  then z nested, z fastest. A player that a client drives moves when its client sends a movement
  packet (at least every 20 ticks, at the client's own time): not modelled.

Sources (decompiled): world/entity/Entity.java (26.1.2: applyEffectsFromBlocks, checkInsideBlocks,
isAffectedByBlocks; 1.21.3: applyEffectsFromBlocks, checkInsideBlocks; 1.21.1, 1.20.6, 1.19.3,
1.19.2: move, checkInsideBlocks), world/entity/LivingEntity.java (aiStep), server/level/
ServerPlayer.java (onInsideBlock), world/level/BlockGetter.java (boxTraverseBlocks),
world/level/block/{TripWire,EndPortal,LayeredCauldron,LavaCauldron,PowderSnow}Block.java
(getEntityInsideCollisionShape, 1.21.3, 1.21.4 and 1.21.7).
"""
from __future__ import annotations

import math

import numpy as np

from emulator.world import living
from emulator.world.blocks import BlockState
from emulator.world.errors import Unmodelled

EVERY_TICK = (1, 21, 2)  # LivingEntity.aiStep -> applyEffectsFromBlocks
SHRINK_VERSION = (1, 19, 3)  # checkInsideBlocks: the box shrunk by 1.0E-7, before by 0.001
DEFLATE = float(np.float32(1.0E-5))  # deflate((double)1.0E-5F)
LONG_MOVE = float(np.float32(0.99999) * np.float32(0.99999))  # boxTraverseBlocks: Mth.square(0.99999F), a float
_OWN_SHAPES = (frozenset({"minecraft:tripwire", "minecraft:end_portal"}),
               frozenset({"minecraft:tripwire", "minecraft:end_portal", "minecraft:water_cauldron",
                          "minecraft:lava_cauldron", "minecraft:powder_snow_cauldron", "minecraft:powder_snow"}))
# the cauldrons' and powder snow's inside shapes: 1.21.7 has them, 1.21.4 not; 1.21.5 and 1.21.6 are
# not known from the sources here, and reported alike (a block with its own inside shape is reported)
OWN_SHAPE_VERSION = (1, 21, 5)


def entered(state, player, moved) -> list[BlockState]:
    version = state.version
    if version >= EVERY_TICK:
        return _blocks_inside(state, player, moved, version)
    if player not in state.falling:
        raise Unmodelled("enter_block for a player a client drives before 1.21.2 (it fires when the "
                         "client's movement packets move the player)")
    if moved is None:
        return []
    shrink = 1.0E-7 if version >= SHRINK_VERSION else 0.001
    lo, hi = _cells(player.bounding_box, shrink)
    blocks = state.blocks_in(player.dimension)
    return [blocks.get((x, y, z)) for x in range(lo[0], hi[0] + 1) for y in range(lo[1], hi[1] + 1)
            for z in range(lo[2], hi[2] + 1)]


def _blocks_inside(state, player, moved, version) -> list[BlockState]:
    if player.gamemode == "spectator" or living.health(player) <= 0:
        return []
    blocks = state.blocks_in(player.dimension)
    box = player.bounding_box
    if moved is not None and sum((b - a) ** 2 for a, b in zip(*moved)) >= LONG_MOVE:
        _refuse_long_move(blocks, box, moved)
    lo, hi = _cells(box, DEFLATE)
    own_shapes = _OWN_SHAPES[version >= OWN_SHAPE_VERSION]
    found = []
    for z in range(lo[2], hi[2] + 1):
        for y in range(lo[1], hi[1] + 1):
            for x in range(lo[0], hi[0] + 1):
                block = blocks.get((x, y, z))
                if block.is_air:
                    continue
                if block.id in own_shapes:
                    raise Unmodelled(f"a player inside {block.id} (whether it meets the block's inside shape)")
                found.append(block)
    return found


def _refuse_long_move(blocks, box, moved) -> None:
    """A move of a block or more: the game looks at the blocks on the way; when they are all air
    (what a fall through open air passes) nothing fires on the way, else it is not modelled."""
    (fx, fy, fz), (tx, ty, tz) = moved
    back = (fx - tx, fy - ty, fz - tz)
    start = tuple(box[a] + back[a % 3] for a in range(6))
    swept = tuple(min(box[a], start[a]) for a in range(3)) + tuple(max(box[a], start[a]) for a in range(3, 6))
    lo, hi = _cells(swept, DEFLATE)
    if any(not blocks.get((x, y, z)).is_air for x in range(lo[0], hi[0] + 1) for y in range(lo[1], hi[1] + 1)
           for z in range(lo[2], hi[2] + 1)):
        raise Unmodelled("a player moving a block or more in a tick past blocks (the blocks on its way)")


def _cells(box, shrink: float):
    """The block cells of ``box`` shrunk by ``shrink`` on each side (BlockPos.containing: floor)."""
    lo = tuple(math.floor(box[a] + shrink) for a in range(3))
    hi = tuple(math.floor(box[a + 3] - shrink) for a in range(3))
    return lo, hi
