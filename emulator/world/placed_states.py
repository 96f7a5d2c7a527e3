"""The state a block takes when a player places it (Block.getStateForPlacement with its
BlockPlaceContext): which way it faces from the player's look or the clicked face, a log's axis, a
stair's half and shape, whether it is waterlogged.

- ``state_for_placement(state, player, block_id, properties, target, face, hit)``:
  the placed block's properties (every property of the block: the ones placement decides and the
  block's defaults for the others), or raises Unmodelled for a block whose placement rule is not
  modelled here. ``properties`` is the block's ``{property: values}``.
- ``update_neighbour_stairs(state, pos)``: StairBlock.updateShape of the stairs beside a placed
  block (their shape follows their new neighbour).
- ``horizontal_direction(player)`` (Entity.getDirection: Direction.fromYRot) and
  ``nearest_looking_direction(player)`` (Direction.orderedByNearest(player)[0], float math).

Modelled: facing the player (the opposite of its horizontal direction: lecterns, furnaces, smokers,
blast furnaces, carved pumpkins, jack o'lanterns, looms, stonecutters, glazed terracotta, beehives,
bee nests, ender chests), anvils (clockwise of it), stairs (its direction, the half from the face
and the click height, the shape from the stairs in front and behind), pistons, dispensers,
droppers and barrels (opposite the nearest looking direction), observers (the nearest looking
direction), hoppers (opposite the clicked face, down when vertical), shulker boxes (the clicked
face), end rods (the clicked face, flipped against an end rod facing it), and pillars (logs, wood,
stems, hyphae, basalt, bone, hay, purpur and quartz pillars, chains ...: the clicked face's axis),
campfires (the player's direction, lit unless placed in water, a signal fire over a hay block).

Sources (decompiled 1.21.x and 26.1): world/item/context/BlockPlaceContext.java
(getNearestLookingDirection, getClickedPos), UseOnContext.getHorizontalDirection, core/Direction.java
(orderedByNearest, fromYRot), world/level/block/LecternBlock, AbstractFurnaceBlock,
CarvedPumpkinBlock, LoomBlock, StonecutterBlock, GlazedTerracottaBlock, BeehiveBlock,
EnderChestBlock, AnvilBlock, StairBlock (getStateForPlacement, getStairsShape, canTakeShape),
piston/PistonBaseBlock, DispenserBlock, BarrelBlock, ObserverBlock, HopperBlock, ShulkerBoxBlock,
EndRodBlock, RotatedPillarBlock, ChainBlock, CampfireBlock (getStateForPlacement, isSmokeSource).
"""
from __future__ import annotations

import math

import numpy as np

from emulator.world import mth
from emulator.world.blocks import BlockState
from emulator.world.errors import Unmodelled
from emulator.world.inventories import CAMPFIRES

F32 = np.float32
HORIZONTAL = ("south", "west", "north", "east")  # Direction's 2D data values 0-3
OPPOSITE = {"up": "down", "down": "up", "north": "south", "south": "north", "west": "east", "east": "west"}
CLOCKWISE = {"north": "east", "east": "south", "south": "west", "west": "north"}
AXIS = {"up": "y", "down": "y", "north": "z", "south": "z", "west": "x", "east": "x"}
OFFSETS = {"up": (0, 1, 0), "down": (0, -1, 0), "north": (0, 0, -1), "south": (0, 0, 1), "west": (-1, 0, 0),
           "east": (1, 0, 0)}

_FACING_PLAYER = frozenset("minecraft:" + n for n in (
    "lectern furnace smoker blast_furnace carved_pumpkin jack_o_lantern loom stonecutter beehive bee_nest "
    "ender_chest").split())
_ANVILS = frozenset(("minecraft:anvil", "minecraft:chipped_anvil", "minecraft:damaged_anvil"))
_LOOKING_AWAY = frozenset("minecraft:" + n for n in "piston sticky_piston dispenser dropper barrel".split())
# the defaults of the properties placement leaves as they are (Block.registerDefaultState)
_DEFAULTS = {"has_book": "false", "powered": "false", "lit": "false", "extended": "false", "triggered": "false",
             "open": "false", "enabled": "true", "waterlogged": "false"}


def horizontal_direction(player) -> str:
    """Entity.getDirection: Direction.fromYRot(yRot) = from2DDataValue(floor(yRot / 90 + 0.5) & 3)."""
    return HORIZONTAL[math.floor(float(player.yaw) / 90.0 + 0.5) & 3]


def nearest_looking_direction(player) -> str:
    """Direction.orderedByNearest(player)[0]."""
    return ordered_by_nearest(player)[0]


def ordered_by_nearest(player) -> list[str]:
    """Direction.orderedByNearest: the six directions from the nearest to the player's look (float math)."""
    pitch = F32(player.pitch) * F32(math.pi / 180)
    yaw = -F32(player.yaw) * F32(math.pi / 180)
    pitch_sin, pitch_cos, yaw_sin, yaw_cos = mth.sin(pitch), mth.cos(pitch), mth.sin(yaw), mth.cos(yaw)
    x_pos, y_pos, z_pos = yaw_sin > 0, pitch_sin < 0, yaw_cos > 0
    x_yaw = yaw_sin if x_pos else -yaw_sin
    y_mag = -pitch_sin if y_pos else pitch_sin
    z_yaw = yaw_cos if z_pos else -yaw_cos
    x_mag, z_mag = x_yaw * pitch_cos, z_yaw * pitch_cos
    x, y, z = ("east" if x_pos else "west"), ("up" if y_pos else "down"), ("south" if z_pos else "north")
    if x_yaw > z_yaw:
        first = (y, x, z) if y_mag > x_mag else ((x, z, y) if z_mag > y_mag else (x, y, z))
    else:
        first = (y, z, x) if y_mag > z_mag else ((z, x, y) if x_mag > y_mag else (z, y, x))
    return [*first, OPPOSITE[first[2]], OPPOSITE[first[1]], OPPOSITE[first[0]]]  # makeDirectionArray


def _is_pillar(properties: dict) -> bool:
    return set(properties) <= {"axis", "waterlogged"} and "axis" in properties


def state_for_placement(state, player, block_id: str, properties: dict, target, face: str, hit) -> dict:
    """getStateForPlacement for ``block_id`` placed at ``target`` by a click on ``face`` at ``hit``."""
    water = state.blocks.get(target).id == "minecraft:water"
    if block_id in _FACING_PLAYER or block_id.endswith("_glazed_terracotta"):
        placed = {"facing": OPPOSITE[horizontal_direction(player)]}
    elif block_id in _ANVILS:
        placed = {"facing": CLOCKWISE[horizontal_direction(player)]}
    elif block_id in _LOOKING_AWAY:
        placed = {"facing": OPPOSITE[nearest_looking_direction(player)]}
    elif block_id == "minecraft:observer":
        placed = {"facing": nearest_looking_direction(player)}
    elif block_id == "minecraft:hopper":
        away = OPPOSITE[face]
        placed = {"facing": "down" if AXIS[away] == "y" else away}
    elif block_id.endswith("shulker_box"):
        placed = {"facing": face}
    elif block_id == "minecraft:end_rod":
        placed = {"facing": _end_rod(state, target, face)}
    elif block_id.endswith("_stairs"):
        placed = _stairs(state, player, target, face, hit)
    elif block_id in CAMPFIRES:
        below = state.blocks.get((target[0], target[1] - 1, target[2]))
        placed = {"facing": horizontal_direction(player), "lit": "false" if water else "true",
                  "signal_fire": "true" if below.id == "minecraft:hay_block" else "false"}
    elif _is_pillar(properties):
        placed = {"axis": AXIS[face]}
    else:
        raise Unmodelled(f"placing {block_id} (its state follows how it is placed: {', '.join(sorted(properties))})")
    if "waterlogged" in properties:
        placed["waterlogged"] = "true" if water else "false"
    missing = [p for p in properties if p not in placed and p not in _DEFAULTS]
    if missing:
        raise Unmodelled(f"placing {block_id} (its {', '.join(missing)} when placed)")
    return {p: placed.get(p, _DEFAULTS.get(p)) for p in properties}


def _end_rod(state, target, face: str) -> str:
    """EndRodBlock: against an end rod facing the clicked face, the new one faces the other way."""
    dx, dy, dz = OFFSETS[OPPOSITE[face]]
    behind = state.blocks.get((target[0] + dx, target[1] + dy, target[2] + dz))
    return OPPOSITE[face] if behind.id == "minecraft:end_rod" and _property(behind, "facing") == face else face


def _stairs(state, player, target, face: str, hit) -> dict:
    """StairBlock.getStateForPlacement: the player's direction, the top half when the bottom face was
    clicked or a side above the block's middle, the shape from the neighbouring stairs."""
    facing = horizontal_direction(player)
    top = face == "down" or (face != "up" and hit[1] - target[1] > 0.5)
    half = "top" if top else "bottom"
    return {"facing": facing, "half": half, "shape": _stairs_shape(state, target, facing, half)}


def _stairs_shape(state, pos, facing: str, half: str) -> str:
    """StairBlock.getStairsShape: a stair behind (in the facing) turned across makes an outer
    corner, one in front an inner corner, unless a stair beside already carries the shape."""
    behind = _stair(state, pos, facing)
    if behind is not None and behind[1] == half and AXIS[behind[0]] != AXIS[facing] and \
            _can_take_shape(state, pos, facing, half, OPPOSITE[behind[0]]):
        return "outer_left" if behind[0] == _counter_clockwise(facing) else "outer_right"
    front = _stair(state, pos, OPPOSITE[facing])
    if front is not None and front[1] == half and AXIS[front[0]] != AXIS[facing] and \
            _can_take_shape(state, pos, facing, half, front[0]):
        return "inner_left" if front[0] == _counter_clockwise(facing) else "inner_right"
    return "straight"


def update_neighbour_stairs(state, pos) -> None:
    """The horizontal neighbours' StairBlock.updateShape after ``pos`` changed."""
    for direction in HORIZONTAL:
        dx, dy, dz = OFFSETS[direction]
        there = (pos[0] + dx, pos[1] + dy, pos[2] + dz)
        found = _stair(state, pos, direction)
        if found is None:
            continue
        block = state.blocks.get(there)
        shape = _stairs_shape(state, there, *found)
        if dict(block.properties).get("shape") != shape:
            state.blocks.set_state(there, BlockState(block.id, tuple(sorted({**dict(block.properties),
                                                                             "shape": shape}.items()))))


def _can_take_shape(state, pos, facing: str, half: str, side: str) -> bool:
    there = _stair(state, pos, side)
    return there is None or there != (facing, half)


def _counter_clockwise(direction: str) -> str:
    return next(k for k, v in CLOCKWISE.items() if v == direction)


def _stair(state, pos, direction: str):
    """(facing, half) of the stairs next to ``pos`` in ``direction``, None when no stairs are there."""
    dx, dy, dz = OFFSETS[direction]
    there = state.blocks.get((pos[0] + dx, pos[1] + dy, pos[2] + dz))
    if not there.id.endswith("_stairs"):
        return None
    return _property(there, "facing"), _property(there, "half")


def _property(block, name: str) -> str:
    """A neighbour's property as placed; one set by default only is not known here."""
    found = dict(block.properties).get(name)
    if found is None:
        raise Unmodelled(f"the default {name} of the neighbouring {block.id} (placing beside it reads it)")
    return found
