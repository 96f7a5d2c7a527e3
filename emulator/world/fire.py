"""Fire a player lights with flint and steel (FlintAndSteelItem.useOn), with what a datapack
observes: the lit campfire or candle, the fire block, a nether portal filling an obsidian frame,
the ``placed_block`` criterion and the item's wear.

- ``flint_and_steel(state, player, hand, access, stack, pos, face) -> str``: the use on the block at
  ``pos`` clicked on ``face``: ``"consume"`` or ``"fail"``.
- ``find_empty_portal(blocks, pos, axis, low)``: PortalShape.findEmptyPortalShape: the portal's
  cells (bottom left first) and axis, or None.

The rules (1.21): a campfire or candle (or candle cake) that is unlit and not waterlogged is lit
(``lit=true``). Else the fire goes in the block in front of the clicked face, which must be air:
- in the overworld or the nether, when that block is inside an empty obsidian frame (PortalShape:
  2 to 21 wide along x, else along z, 3 to 21 high, the frame's corners not needed), the frame fills
  with ``nether_portal[axis=x|z]`` at once (BaseFireBlock.onPlace). Lit from a cell whose fire could
  not stand there (BaseFireBlock.canBePlacedAt), the frame must touch that cell (an obsidian
  neighbour: isPortal);
- else, on a block whose top face is sturdy, a fire: ``soul_fire`` on soul sand or soul soil
  (#soul_fire_base_blocks), else ``fire`` with age 0 and no sides (FireBlock.getStateForPlacement).
  Where it stands on no sturdy face it burns only beside flammable blocks, which the emulator does
  not know: not modelled. The fire's own ticks (ageing, spreading, going out: FireBlock.tick,
  first due 30 to 39 ticks after it was lit) are not modelled: a fire still there when its first
  tick could come is reported as not modelled, unless doFireTick is false (from 1.21.11,
  fire_spread_radius_around_player 0), when the tick does nothing but come again.
The use then fires ``placed_block`` at the fire's block with the flint and steel, and wears it by
one (ItemStack.hurtAndBreak: Unbreaking, breaking, not in creative); lighting a campfire or candle
wears it without ``placed_block``. Game events and sounds are not observable by a pack.

Sources (decompiled 1.21): world/item/FlintAndSteelItem.java (useOn), world/level/block/
BaseFireBlock.java (getState, canBePlacedAt, isPortal, onPlace, inPortalDimension), FireBlock.java
(getStateForPlacement, canSurvive, onPlace: getFireTickDelay), SoulFireBlock.canSurviveOnBlock,
CampfireBlock.canLight, CandleBlock.canLight, CandleCakeBlock.canLight,
world/level/portal/PortalShape.java (findEmptyPortalShape, calculateBottomLeft, calculateWidth,
calculateHeight, createPortalBlocks).
"""
from __future__ import annotations

from emulator.world import advancements, block_shapes, tools
from emulator.world.blocks import BlockState
from emulator.world.errors import Unmodelled
from emulator.world.inventories import CAMPFIRES
from emulator.world.placed_states import OFFSETS

FIRE_TICK_DELAY = 30  # FireBlock.getFireTickDelay: 30 + nextInt(10); the earliest its first tick comes
MIN_WIDTH, MAX_WIDTH, MIN_HEIGHT, MAX_HEIGHT = 2, 21, 3, 21  # PortalShape
PORTAL_DIMENSIONS = ("minecraft:overworld", "minecraft:the_nether")  # BaseFireBlock.inPortalDimension
SOUL_FIRE_BASE = ("minecraft:soul_sand", "minecraft:soul_soil")  # #minecraft:soul_fire_base_blocks
_RIGHT = {"x": (-1, 0, 0), "z": (0, 0, 1)}  # PortalShape.rightDir: WEST along x, SOUTH along z
_EMPTY = ("minecraft:air", "minecraft:cave_air", "minecraft:void_air", "minecraft:fire", "minecraft:soul_fire",
          "minecraft:nether_portal")  # PortalShape.isEmpty: air, #fire, a portal
_OBSIDIAN = "minecraft:obsidian"
_FIRE_SIDES = ("east", "north", "south", "up", "west")


def _property(block, name: str, default: str = "") -> str:
    return dict(block.properties).get(name, default)


def _can_light(block) -> bool:
    """CampfireBlock / CandleBlock / CandleCakeBlock.canLight: unlit and not waterlogged."""
    name = block.id.removeprefix("minecraft:")
    lightable = block.id in CAMPFIRES or name.endswith("candle") or name.endswith("candle_cake")
    return lightable and _property(block, "lit") == "false" and _property(block, "waterlogged", "false") == "false"


def _set(state, pos, block_id: str, properties: dict) -> None:
    state.blocks.set_state(pos, BlockState.of(block_id, properties))


def flint_and_steel(state, player, hand: str, access, stack, pos, face: str) -> str:
    """FlintAndSteelItem.useOn (see the module's doc)."""
    blocks = state.blocks
    clicked = blocks.get(pos)
    if _can_light(clicked):
        _set(state, pos, clicked.id, {**dict(clicked.properties), "lit": "true"})
        tools.hurt_and_break(state, player, access, 1)
        return "consume"
    dx, dy, dz = OFFSETS[face]
    target = (pos[0] + dx, pos[1] + dy, pos[2] + dz)
    if not blocks.get(target).is_air:
        return "fail"
    low, _ = state.entities.table.levels.build_height(player.dimension, state.version)
    portal = find_empty_portal(blocks, target, "x", low) if player.dimension in PORTAL_DIMENSIONS else None
    below = blocks.get((target[0], target[1] - 1, target[2]))
    # canBePlacedAt: the fire can stand (a sturdy top below it; beside what burns is not known
    # here), or the cell is in a frame it touches (isPortal)
    if not block_shapes.is_face_sturdy(below) and not (portal is not None and _touches_obsidian(blocks, target)):
        raise Unmodelled(f"lighting a fire over {below.id} (whether the blocks around it burn: FireBlock.canBurn)")
    if portal is not None:
        cells, axis = portal
        for cell in cells:
            _set(state, cell, "minecraft:nether_portal", {"axis": axis})
    elif below.id in SOUL_FIRE_BASE:
        _set(state, target, "minecraft:soul_fire", {})
    else:
        _set(state, target, "minecraft:fire", {"age": "0", **{side: "false" for side in _FIRE_SIDES}})
        state.block_ticks.schedule(target, "minecraft:fire", FIRE_TICK_DELAY, state.gametime, _unmodelled_fire_tick)
    advancements.trigger(state, player, "placed_block", advancements.location_test(state, player, target, stack))
    tools.hurt_and_break(state, player, access, 1)
    return "consume"


SPREAD_RADIUS_RULE = (1, 21, 11)  # fire_spread_radius_around_player replaced doFireTick


def _unmodelled_fire_tick(state, pos) -> None:
    """FireBlock.tick: the next tick is scheduled, then with doFireTick (from 1.21.11, a
    fire_spread_radius_around_player that is not 0: ServerLevel.canSpreadFireAround) the fire ages,
    spreads and goes out, which is not modelled. Without it the fire stays: nothing to model."""
    if tuple(state.version) >= SPREAD_RADIUS_RULE:
        still = state.gamerules.get("fire_spread_radius_around_player") == "0"
    else:
        still = state.gamerules.get("doFireTick") == "false"
    if still:  # the next tick's delay (30 + nextInt(10)) draws from the level's random: its earliest
        state.block_ticks.schedule(pos, "minecraft:fire", FIRE_TICK_DELAY, state.gametime, _unmodelled_fire_tick)
        return
    state.error(f"the fire at {pos[0]} {pos[1]} {pos[2]} burning on (FireBlock.tick: ageing, spreading, "
                "going out)", severity="warning", unmodelled=True)


def _touches_obsidian(blocks, pos) -> bool:
    return any(blocks.get((pos[0] + dx, pos[1] + dy, pos[2] + dz)).id == _OBSIDIAN for dx, dy, dz in OFFSETS.values())


def find_empty_portal(blocks, pos, axis: str, low: int):
    """PortalShape.findEmptyPortalShape: the shape along ``axis``, else the other axis, that is
    valid and holds no portal block yet: (its cells, its axis), or None."""
    for along in (axis, "z" if axis == "x" else "x"):
        shape = _portal_shape(blocks, tuple(pos), along, low)
        if shape is not None:
            return shape, along
    return None


def _step(pos, direction, n: int = 1):
    return (pos[0] + direction[0] * n, pos[1] + direction[1] * n, pos[2] + direction[2] * n)


def _is_empty(blocks, pos) -> bool:
    return blocks.get(pos).id in _EMPTY


def _is_frame(blocks, pos) -> bool:
    return blocks.get(pos).id == _OBSIDIAN


def _distance_until_edge_above_frame(blocks, start, direction) -> int:
    """PortalShape.getDistanceUntilEdgeAboveFrame: empty cells over obsidian up to an obsidian side."""
    for i in range(MAX_WIDTH + 1):
        cell = _step(start, direction, i)
        if not _is_empty(blocks, cell):
            return i if _is_frame(blocks, cell) else 0
        if not _is_frame(blocks, (cell[0], cell[1] - 1, cell[2])):
            return 0
    return 0


def _portal_shape(blocks, pos, axis: str, low: int):
    """new PortalShape(level, pos, axis) filtered by isValid and no portal block: its cells."""
    right = _RIGHT[axis]
    left = (-right[0], -right[1], -right[2])
    floor = max(low, pos[1] - MAX_HEIGHT)  # calculateBottomLeft: down through the empty cells
    while pos[1] > floor and _is_empty(blocks, (pos[0], pos[1] - 1, pos[2])):
        pos = (pos[0], pos[1] - 1, pos[2])
    back = _distance_until_edge_above_frame(blocks, pos, left) - 1
    if back < 0:
        return None
    bottom_left = _step(pos, left, back)
    width = _distance_until_edge_above_frame(blocks, bottom_left, right)
    if not MIN_WIDTH <= width <= MAX_WIDTH:
        return None
    height, portals = _distance_until_top(blocks, bottom_left, right, width)
    if not MIN_HEIGHT <= height <= MAX_HEIGHT or portals:
        return None
    if not all(_is_frame(blocks, _step((bottom_left[0], bottom_left[1] + height, bottom_left[2]), right, i))
               for i in range(width)):  # hasTopFrame
        return None
    return [_step((bottom_left[0], bottom_left[1] + up, bottom_left[2]), right, i)
            for up in range(height) for i in range(width)]


def _distance_until_top(blocks, bottom_left, right, width: int):
    """PortalShape.getDistanceUntilTop: rows with obsidian at both ends and empty between, and the
    portal blocks counted on the way."""
    portals = 0
    for up in range(MAX_HEIGHT):
        row = (bottom_left[0], bottom_left[1] + up, bottom_left[2])
        if not _is_frame(blocks, _step(row, right, -1)) or not _is_frame(blocks, _step(row, right, width)):
            return up, portals
        for i in range(width):
            cell = _step(row, right, i)
            if not _is_empty(blocks, cell):
                return up, portals
            portals += blocks.get(cell).id == "minecraft:nether_portal"
    return MAX_HEIGHT, portals
