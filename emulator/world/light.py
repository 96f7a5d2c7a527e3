"""Light as location predicates read it: whether a block sees the sky (``can_see_sky``) and its
light level (``light``), in the emulator's world, empty where nothing was placed.

- ``can_see_sky(state, dimension, pos)``: BlockAndTintGetter.canSeeSky, the sky light there at its
  maximum (15). Sky light keeps 15 only straight down through blocks that let it pass whole (no
  light dampening, no face of their light occlusion shape in the way); any other path loses light.
  In the emulator's world, empty where nothing was placed, that is: the block itself and every
  block above it pass it. Levels without sky light (the nether, the end) never see it. A block in
  the way whose light properties the emulator does not know is not modelled.
- ``brightness(state, dimension, pos)``: Level.getMaxLocalRawBrightness, the larger of the block
  light and the sky light less the sky's darkening. Known where the block sees the sky (sky light
  15) or in a level without sky light, and no block within 14 steps could give light (a light
  source, or a block the emulator does not know): then the block light is 0. Anything else is
  not modelled.
- ``sky_darken(daytime)``: Level.updateSkyBrightness in clear weather, from the day time (ServerLevel
  keeps it from its start and updates it each tick before the time advances: ``state.sky_darken``).

What passes: air, glass and stained glass (TransparentBlock.propagatesSkylightDown), barriers and
light blocks when not waterlogged, torches and signs when not waterlogged (small shapes, no
fluid: propagatesSkylightDown), and at the block itself a bottom slab or bottom stairs (their top
face leaves room). What stops it: every other full cube (opaque ones dampen it fully; leaves, ice,
slime and honey blocks, tinted glass by 1 or more), water and lava and anything waterlogged (a
fluid dampens by 1), and above the block any slab or stairs (one of their faces is full).

Sources (decompiled 1.21): world/level/BlockAndTintGetter.canSeeSky, Level.updateSkyBrightness,
DimensionType.timeOfDay, LevelReader.getMaxLocalRawBrightness, lighting/LevelLightEngine.
getRawBrightness, ServerLevel (its constructor and tick), block/state/BlockBehaviour
(getLightBlock: solid render 15, else 0 when propagatesSkylightDown, else 1; propagatesSkylightDown:
a shape that is not a full block and no fluid), TransparentBlock, TintedGlassBlock, BarrierBlock,
LightBlock, LeavesBlock, world/level/lighting/LightEngine.shapeOccludes, SkyLightEngine,
dimension types' has_skylight.
"""
from __future__ import annotations

import math

from emulator.world import block_shapes, mth
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
    raise Unmodelled(f"how {block.id} lets sky light through is not known here")


def can_see_sky(state, dimension: str, pos) -> bool:
    if dimension in SKYLESS:
        return False
    if dimension != "minecraft:overworld":
        raise Unmodelled(f"the sky light of {dimension}'s dimension type")
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


# blocks whose shape the emulator knows that give light in some state (BlockBehaviour.Properties.lightLevel)
_LIGHT_SOURCES = frozenset("minecraft:" + n for n in (
    "glowstone sea_lantern jack_o_lantern redstone_lamp magma_block shroomlight ochre_froglight verdant_froglight "
    "pearlescent_froglight crying_obsidian respawn_anchor furnace smoker blast_furnace sculk_catalyst redstone_ore "
    "deepslate_redstone_ore fire soul_fire lava light glow_lichen torch wall_torch beacon").split())
LIGHT_REACH = 14  # a light of 15 loses at least 1 a step


def _dark(block) -> bool:
    """Whether the block gives no light in any state (it is known here and no light source)."""
    if block.id in _LIGHT_SOURCES or block.id.endswith("_torch"):
        return False
    if block.id.endswith(("_slab", "_stairs", "_sign")):
        return True
    try:
        block_shapes.collides(block)
    except Unmodelled:
        return False
    return True


def sky_darken(daytime: int) -> int:
    """Level.updateSkyBrightness with no rain or thunder: (int)((1 - d2) * 11), d2 = 0.5 + 2 x
    clamp(Mth.cos(timeOfDay x 2 pi), -0.25, 0.25) (DimensionType.timeOfDay of the day time)."""
    d0 = math.fmod(daytime / 24000.0 - 0.25, 1.0)
    d0 = d0 + 1.0 if d0 < 0 else d0  # Mth.frac
    d1 = 0.5 - math.cos(d0 * math.pi) / 2.0
    time_of_day = mth.f32((d0 * 2.0 + d1) / 3.0)
    d2 = 0.5 + 2.0 * min(max(float(mth.cos(mth.f32(time_of_day * mth.f32(math.pi * 2)))), -0.25), 0.25)
    return int((1.0 - d2) * 11.0)


def brightness(state, dimension: str, pos) -> int:
    if state.clocks is not None:
        raise Unmodelled("the sky's darkening by the world clocks' environment attributes (26.1+)")
    sky = 0 if dimension in SKYLESS else 15 if can_see_sky(state, dimension, pos) else None
    if sky is None:
        raise Unmodelled("sky light that does not come straight down (the emulator keeps no light engine)")
    x, y, z = pos
    for (bx, by, bz), block in state.blocks_in(dimension).states.items():
        if abs(bx - x) + abs(by - y) + abs(bz - z) <= LIGHT_REACH and not _dark(block):
            raise Unmodelled(f"block light from {block.id} (the emulator keeps no light engine)")
    return max(0, sky - state.sky_darken)
