"""Light as location predicates read it: whether a block sees the sky (``can_see_sky``) and its
light level (``light``), in the emulator's world, empty where nothing was placed.

- ``can_see_sky(state, dimension, pos)``: BlockAndTintGetter.canSeeSky, the sky light there at its
  maximum (15). Sky light keeps 15 only straight down through blocks that let it pass whole (no
  light dampening, no face of their light occlusion shape in the way); any other path loses light.
  In the emulator's world, empty where nothing was placed, that is: the block itself and every
  block above it pass it. Levels without sky light (the nether, the end) never see it. A block in
  the way whose light properties the emulator does not know is not modelled.
- ``brightness(state, dimension, pos)``: Level.getMaxLocalRawBrightness, the larger of the block
  light and the sky light less the sky's darkening. Block light (BlockLightEngine) starts at each
  block's emission in its state (``emission``); sky light (SkyLightEngine) at 15 where a block sees
  the sky; both lose max(1, getLightBlock) of the block they enter at each step (``light_block``),
  so they spread down and sideways under roofs and round opaque blocks. Only the blocks within 15
  steps of the position are read, when a pack asks and from the world as it is then (nothing is
  kept between reads, so a block changed by any command shows at once). A block within reach
  whose emission, or on the way whose light dampening, is not known here (a slab, stairs or fence
  occluding light with a face: LightEngine.shapeOccludes) is not modelled.
- ``sky_darken(daytime)``: Level.updateSkyBrightness in clear weather, from the day time (ServerLevel
  keeps it from its start and updates it each tick before the time advances: ``state.sky_darken``,
  worked out from ``state.sky_time`` when read).

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
LightBlock, LeavesBlock, world/level/lighting/LightEngine (getOpacity, shapeOccludes), BlockLightEngine
(propagateIncrease), SkyLightEngine, Blocks (lightLevel: litBlockEmission, CandleBlock, SeaPickleBlock,
RespawnAnchorBlock.getScaledChargeLevel, CaveVines.emission),
dimension types' has_skylight.
"""
from __future__ import annotations

import functools
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


@functools.lru_cache(maxsize=4096)  # per block state: read for every step through it
def _passes(block, at_block: bool) -> bool:
    """Whether sky light 15 is still 15 in ``block`` (``at_block``) or below it: nothing dampens it
    (:func:`light_block` 0) and no face of the block's shape is in the way."""
    if block.id.endswith(("_slab", "_stairs")) and dict(block.properties).get("type") != "double":
        waterlogged = dict(block.properties).get("waterlogged") == "true"
        return at_block and not waterlogged and dict(block.properties).get("type", dict(block.properties).get(
            "half")) == "bottom"
    return light_block(block) == 0


def can_see_sky(state, dimension: str, pos) -> bool:
    return _sky_reader(state, dimension)(tuple(pos))


def _sky_reader(state, dimension: str):
    """``can_see_sky`` for the level's positions, its placed blocks grouped by column once."""
    if dimension in SKYLESS:
        return lambda pos: False
    if dimension != "minecraft:overworld":
        raise Unmodelled(f"the sky light of {dimension}'s dimension type")
    blocks = state.blocks_in(dimension)
    columns: dict = {}
    for (bx, by, bz), block in blocks.states.items():
        columns.setdefault((bx, bz), []).append((by, block))

    def sees(pos) -> bool:
        x, y, z = pos
        column = [(blocks.get(pos), True)] + [(block, False) for by, block in columns.get((x, z), ()) if by > y]
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
    return sees


# BlockBehaviour.Properties.lightLevel per block (Blocks.java): a constant, or read from the state
_EMISSION = {"minecraft:" + n: int(v) for n, v in (e.split("=") for e in (
    "glowstone=15 sea_lantern=15 jack_o_lantern=15 lantern=15 soul_lantern=10 shroomlight=15 ochre_froglight=15 "
    "verdant_froglight=15 pearlescent_froglight=15 beacon=15 conduit=15 end_rod=14 torch=14 wall_torch=14 "
    "soul_torch=10 soul_wall_torch=10 fire=15 soul_fire=10 lava=15 magma_block=3 crying_obsidian=10 "
    "sculk_catalyst=6 glow_lichen=7 end_portal=15 end_gateway=15 nether_portal=11 enchanting_table=7 "
    "ender_chest=7 brewing_stand=1 dragon_egg=1 brown_mushroom=1 amethyst_cluster=5 large_amethyst_bud=4 "
    "medium_amethyst_bud=2 small_amethyst_bud=1 end_portal_frame=1 sculk_sensor=1 calibrated_sculk_sensor=1 "
    "lava_cauldron=15").split())}
# lightLevel read from a ``state`` property (VaultState.LightLevel, TrialSpawnerState's lightLevel)
_BY_STATE = {"minecraft:vault": ("vault_state", {"inactive": 6, "active": 12, "unlocking": 12, "ejecting": 12}),
             "minecraft:trial_spawner": ("trial_spawner_state", {
                 "inactive": 0, "waiting_for_players": 4, "active": 8, "waiting_for_reward_ejection": 8,
                 "ejecting_reward": 8, "cooldown": 0})}
_LIT = {"minecraft:" + n: int(v) for n, v in (e.split("=") for e in (  # litBlockEmission(v): v when lit=true
    "furnace=13 smoker=13 blast_furnace=13 redstone_lamp=15 redstone_torch=7 redstone_wall_torch=7 redstone_ore=9 "
    "deepslate_redstone_ore=9 campfire=15 soul_campfire=10 copper_bulb=15 exposed_copper_bulb=12 "
    "weathered_copper_bulb=8 oxidized_copper_bulb=4 waxed_copper_bulb=15 waxed_exposed_copper_bulb=12 "
    "waxed_weathered_copper_bulb=8 waxed_oxidized_copper_bulb=4").split())}
# getLightBlock (BlockBehaviour: solid render 15, else 0 when propagatesSkylightDown, else 1) of blocks
# that are not a plain opaque cube and have no face that occludes light on its own
_TRANSLUCENT = frozenset("minecraft:" + n for n in (  # full shapes that do not render solid: 1
    "ice frosted_ice slime_block beacon spawner mangrove_roots").split())
_SMALL = frozenset("minecraft:" + n for n in (  # shapes that are not a full block: 0 without a fluid
    "lantern soul_lantern end_rod conduit brewing_stand dragon_egg amethyst_cluster large_amethyst_bud "
    "medium_amethyst_bud small_amethyst_bud campfire soul_campfire sea_pickle cave_vines cave_vines_plant "
    "candle_cake enchanting_table ender_chest chest trapped_chest").split())
LIGHT_REACH = 14  # a light of 15 loses at least 1 a step


@functools.lru_cache(maxsize=4096)  # per block state: read for every step through it
def emission(block) -> int:
    """BlockStateBase.getLightEmission: the block's light level in its state (Blocks.java lightLevel)."""
    properties = dict(block.properties)
    if block.id in _EMISSION:
        return _EMISSION[block.id]
    if block.id in _LIT:
        return _LIT[block.id] if properties.get("lit") == "true" else 0
    if block.id in _BY_STATE:
        key, levels = _BY_STATE[block.id]
        return levels.get(properties.get(key), levels["inactive"])  # inactive: the default state
    if block.id == "minecraft:light":
        return int(properties.get("level", "15"))  # LightBlock.LIGHT_EMISSION
    if block.id.endswith("candle"):  # CandleBlock.LIGHT_EMISSION: 3 per candle when lit
        return 3 * int(properties.get("candles", "1")) if properties.get("lit") == "true" else 0
    if block.id.endswith("candle_cake"):  # CandleCakeBlock: litBlockEmission(3)
        return 3 if properties.get("lit") == "true" else 0
    if block.id == "minecraft:respawn_anchor":  # RespawnAnchorBlock.getScaledChargeLevel(state, 15)
        return int(int(properties.get("charges", "0")) / 4.0 * 15)
    if block.id == "minecraft:sea_pickle":  # SeaPickleBlock.isDead (not waterlogged): 0, else 3 + 3 x pickles
        return 3 + 3 * int(properties.get("pickles", "1")) if properties.get("waterlogged") == "true" else 0
    if block.id in ("minecraft:cave_vines", "minecraft:cave_vines_plant"):  # CaveVines.emission(14)
        return 14 if properties.get("berries") == "true" else 0
    if block.id.endswith(("_slab", "_stairs", "_sign")) or block.id in _SMALL or block.id in _TRANSLUCENT:
        return 0
    block_shapes.collides(block)  # known here (a full cube or no collision) and not a source: dark
    return 0


@functools.lru_cache(maxsize=4096)  # per block state: read for every step through it
def light_block(block) -> int:
    """BlockStateBase.getLightBlock: how much light the block takes away (at least 1 a step:
    LightEngine.getOpacity). Blocks that occlude light by a face of their shape (slabs, stairs,
    fences ...: useShapeForLightOcclusion) are not modelled."""
    if block.id == "minecraft:tinted_glass":
        return 15  # TintedGlassBlock.getLightBlock: the level's maximum
    if dict(block.properties).get("waterlogged") == "true" or block.id in _DAMPENING_FULL:
        return 1  # a fluid: not propagatesSkylightDown, not solid render
    if block.id in _CLEAR or block.id.endswith(_CLEAR_SUFFIXES) or block.id in _SMALL or block.id.endswith("candle"):
        return 0
    if block.id in _TRANSLUCENT or block.id.endswith("_leaves"):
        return 1
    if block.id.endswith(("_slab", "_stairs")) and dict(block.properties).get("type") != "double":
        raise Unmodelled(f"how {block.id} occludes light with its faces (LightEngine.shapeOccludes)")
    if block_shapes.collides(block):
        return 15  # a full cube that renders solid
    return 0  # no collision: not a full shape, so it lets light through


def _light_at(state, dimension: str, pos, sources) -> int:
    """The light at ``pos`` from ``sources`` (position -> level there), as LightEngine.propagateIncrease
    spreads it: a neighbour gets the level less max(1, its getLightBlock). Searched backwards from
    ``pos`` (cheapest paths first), so only blocks within 15 steps are read."""
    blocks = state.blocks_in(dimension)
    start = tuple(pos)
    cost = {start: 0}
    frontier = [[] for _ in range(16)]
    frontier[0].append(start)
    best = 0
    for spent in range(15):
        for cell in frontier[spent]:
            if cost[cell] != spent:
                continue
            level = sources(cell)
            if level - spent > best:
                best = level - spent
                if best == 15:
                    return best
            step = spent + max(1, light_block(blocks.get(cell)))  # what light entering ``cell`` loses
            if step >= 15 or best >= 15 - step:
                continue
            x, y, z = cell
            for near in ((x + 1, y, z), (x - 1, y, z), (x, y + 1, z), (x, y - 1, z), (x, y, z + 1), (x, y, z - 1)):
                if step < cost.get(near, 16):
                    cost[near] = step
                    frontier[step].append(near)
    return best


def block_light(state, dimension: str, pos) -> int:
    """BlockLightEngine: the light from emitting blocks at ``pos``. A placed block within reach whose
    light emission is not known here is not modelled."""
    x, y, z = pos
    lit = {}
    for (bx, by, bz), block in state.blocks_in(dimension).states.items():
        if abs(bx - x) + abs(by - y) + abs(bz - z) <= LIGHT_REACH:
            try:
                level = emission(block)
            except Unmodelled:
                raise Unmodelled(f"block light from {block.id}: whether it gives light is not known here") from None
            if level:
                lit[(bx, by, bz)] = level
    if not lit:
        return 0
    return _light_at(state, dimension, pos, lambda cell: lit.get(cell, 0))


def sky_light(state, dimension: str, pos) -> int:
    """SkyLightEngine: 15 where the block sees the sky (straight down, :func:`can_see_sky`), from there
    down and sideways under roofs losing max(1, getLightBlock) a step; 0 in levels without sky light."""
    if dimension in SKYLESS:
        return 0
    sees = _sky_reader(state, dimension)
    return _light_at(state, dimension, pos, lambda cell: 15 if sees(cell) else 0)


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
    x, y, z = pos
    lit = block_light(state, dimension, (x, y, z))
    if lit >= 15 - state.sky_darken:  # the sky cannot give more: not read
        return lit
    return max(lit, sky_light(state, dimension, (x, y, z)) - state.sky_darken)
