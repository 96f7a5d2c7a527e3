"""Blocks that act on a mob standing in or on them, which the emulator does not model: reported as
not modelled, once per block, while a living mob (a mob, a player, an armor stand) is where the
block would act on it; likewise a minecart that would ride its rails (with motion, or on a powered
rail). Entities do not move here, so the game's outcome (a tilted leaf, a pressed plate, a burn, a
cart up the track) never comes, and a test waiting for it must not fail as if the pack were wrong.

- ``tick_report(state)``: the report, each tick after the entities' other steps;
  ``tick_is_idle(state)``: nothing left to report.

The blocks (decompiled 1.21, world/level/block/): BigDripleafBlock.entityInside (an entity on the
leaf tilts it: onGround and above y + 0.6875), BasePressurePlateBlock.entityInside (pressed),
TripWireBlock.entityInside (triggered), MagmaBlock.stepOn (hurts), BaseFireBlock.entityInside and
lava (Entity.lavaHurt: set on fire, hurt), FarmBlock.fallOn (trampled
only by a fall, which needs movement: not listed), PowderSnowBlock.entityInside (freezes).
Where the game looks: the block at the feet (Entity.checkInsideBlocks covers the bounding box; the
feet are where these blocks sit) and the block under them (Entity.getOnPos: 0.2 below the feet).
"""
from __future__ import annotations

import math

MESSAGE = "a mob standing in or on {} (what the block does to it is not modelled here)"
CART = "a minecart {} (a minecart riding its rails is not modelled here)"
_INSIDE_SUFFIXES = ("_pressure_plate",)
_INSIDE = frozenset({"minecraft:big_dripleaf", "minecraft:tripwire", "minecraft:powder_snow", "minecraft:fire",
                    "minecraft:soul_fire", "minecraft:lava"})
_STEP_ON = frozenset({"minecraft:magma_block"})
_ON_POS_OFFSET = 0.2  # Entity.getOnPos(): getOnPos(0.2F)


def _acts_inside(block_id: str) -> bool:
    return block_id in _INSIDE or block_id.endswith(_INSIDE_SUFFIXES)


def _acts(block_id: str) -> bool:
    return _acts_inside(block_id) or block_id in _STEP_ON


def _holds_acting(blocks) -> bool:
    """Whether any block of the level would act on a mob (the common world has none: no mob's
    position need be read)."""
    return blocks.derived("acting on mobs", _find_acting)


def _find_acting(blocks) -> bool:
    return any(_acts(s.id) for s in blocks.states.values())


def _touched(state, entity) -> list[str]:
    """The acting block ids at the mob's feet and under them (both checks: with no gravity a mob
    set above a leaf or plate stays at whole y, where the game would have it resting on it)."""
    blocks = state.level(entity.dimension).blocks
    x, y, z = entity.pos
    column, feet_y, under_y = (math.floor(x), math.floor(z)), math.floor(y), math.floor(y - _ON_POS_OFFSET)
    feet = blocks.get((column[0], feet_y, column[1])).id
    under = feet if under_y == feet_y else blocks.get((column[0], under_y, column[1])).id
    found = [feet] if _acts_inside(feet) and under_y != feet_y else []
    if _acts_inside(under) or under in _STEP_ON:
        found.append(under)
    return found


def _moving_carts(state):
    """Why each minecart would move: its motion, or a powered rail under it (AbstractMinecart.tick:
    moveAlongTrack pushes a cart on a powered one, from standstill when a solid block is at one end)."""
    for cart in state.entities.minecarts():
        if any(float(m) != 0.0 for m in cart.motion):
            yield CART.format("with motion")
            continue
        x, y, z = cart.pos
        rail = state.level(cart.dimension).blocks.get((math.floor(x), math.floor(y), math.floor(z)))
        if rail.id == "minecraft:powered_rail" and ("powered", "true") in rail.properties:
            yield CART.format("on a powered rail")


def _any_acting(state) -> bool:
    others = state.other_levels_blocks  # (none, most ticks: no generator made for them)
    return _holds_acting(state.blocks) or bool(others) and any(_holds_acting(blocks) for blocks in others.values())


def _may_act(state) -> bool:
    """Whether there is anything to look at: a minecart, or a block that acts on a mob."""
    return bool(state.entities.minecarts()) or _any_acting(state)


def _unreported(state):
    carts = state.entities.minecarts()
    mobs = state.entities.living_mobs() if _any_acting(state) else ()
    if not (mobs or carts):
        return
    touched = [MESSAGE.format(block_id) for entity in mobs for block_id in _touched(state, entity)]
    touched += _moving_carts(state) if carts else ()
    if not touched:  # the common tick: no look at the diagnostics
        return
    reported = {d.message for d in state.diagnostics if d.unmodelled}
    for message in touched:
        if message not in reported:
            yield message


def tick_report(state) -> None:
    if not _may_act(state):  # the commonest tick of all
        return
    for message in dict.fromkeys(_unreported(state)):  # in the mobs' order, each once
        state.error(message, severity="warning", unmodelled=True)


def tick_is_idle(state) -> bool:
    return not _may_act(state) or next(_unreported(state), None) is None
