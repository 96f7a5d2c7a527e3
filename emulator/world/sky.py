"""Whether a block sees the sky, as a location predicate's ``can_see_sky`` asks it.

- ``can_see_sky(state, dimension, pos)``: BlockAndTintGetter.canSeeSky, the sky light there at its
  maximum (15). Sky light keeps 15 only straight down through blocks that let it pass whole (no
  light dampening, no face of their light occlusion shape in the way); any other path loses light.
  In the emulator's world, empty where nothing was placed, that is: the block itself and every
  block above it pass it. Levels without sky light (the nether, the end) never see it. A block in
  the way whose light properties the emulator does not know is not modelled.

What passes: air, glass and stained glass (TransparentBlock.propagatesSkylightDown), barriers and
light blocks when not waterlogged, torches and signs when not waterlogged (small shapes, no
fluid: propagatesSkylightDown), and at the block itself a bottom slab or bottom stairs (their top
face leaves room). What stops it: every other full cube (opaque ones dampen it fully; leaves, ice,
slime and honey blocks, tinted glass by 1 or more), water and lava and anything waterlogged (a
fluid dampens by 1), and above the block any slab or stairs (one of their faces is full).

Sources (decompiled 1.21): world/level/BlockAndTintGetter.canSeeSky, block/state/BlockBehaviour
(getLightBlock: solid render 15, else 0 when propagatesSkylightDown, else 1; propagatesSkylightDown:
a shape that is not a full block and no fluid), TransparentBlock, TintedGlassBlock, BarrierBlock,
LightBlock, LeavesBlock, world/level/lighting/LightEngine.shapeOccludes, SkyLightEngine,
dimension types' has_skylight.
"""
from __future__ import annotations

from emulator.world import block_shapes
from emulator.world.errors import Unmodelled

SKYLESS = frozenset({"minecraft:the_nether", "minecraft:the_end"})  # has_skylight false
_CLEAR = frozenset({"minecraft:air", "minecraft:cave_air", "minecraft:void_air", "minecraft:glass",
                    "minecraft:barrier", "minecraft:light", "minecraft:torch", "minecraft:wall_torch"})
_CLEAR_SUFFIXES = ("_stained_glass", "_torch", "_sign")
_DAMPENING_FULL = frozenset({"minecraft:tinted_glass", "minecraft:water", "minecraft:lava", "minecraft:honey_block",
                             "minecraft:cobweb", "minecraft:seagrass", "minecraft:tall_seagrass", "minecraft:kelp",
                             "minecraft:kelp_plant", "minecraft:bubble_column"})


def _passes(block, at_block: bool) -> bool:
    """Whether sky light 15 is still 15 in ``block`` (``at_block``) or below it."""
    properties = dict(block.properties)
    if properties.get("waterlogged") == "true" or block.id in _DAMPENING_FULL:
        return False
    if block.id in _CLEAR or block.id.endswith(_CLEAR_SUFFIXES):
        return True
    if block.id.endswith(("_slab", "_stairs")):
        return at_block and properties.get("type", properties.get("half")) == "bottom"
    try:
        full = block_shapes.collides(block)  # a full cube: it dampens or occludes sky light
    except Unmodelled:
        full = None
    if full:
        return False
    raise Unmodelled(f"location predicate field 'can_see_sky' (how {block.id} lets sky light through is not known here)")


def can_see_sky(state, dimension: str, pos) -> bool:
    if dimension in SKYLESS:
        return False
    if dimension != "minecraft:overworld":
        raise Unmodelled(f"location predicate field 'can_see_sky' (the sky light of {dimension}'s dimension type)")
    blocks = state.blocks_in(dimension)
    x, y, z = pos
    column = [(blocks.get(pos), True)] + [(block, False) for (bx, by, bz), block in blocks.states.items()
                                          if bx == x and bz == z and by > y]
    unknown = None
    for block, at_block in column:  # a block that stops the light decides, whatever the others are
        try:
            if not _passes(block, at_block):
                return False
        except Unmodelled as reason:
            unknown = unknown or reason
    if unknown is not None:
        raise unknown
    return True
