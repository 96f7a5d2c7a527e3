"""Placing blocks that join, come in two parts or hang on a neighbour (Block.getStateForPlacement
and what BlockItem.place does after), with what a datapack observes: the block states.

- slabs: a slab clicked on its open side (or an empty spot beside) becomes a double slab
  (SlabBlock.canBeReplaced, getStateForPlacement), else the half from the clicked face and height;
- doors: both halves (DoorBlock.getStateForPlacement, setPlacedBy), facing the player's direction,
  the hinge from the full blocks and doors beside and the click (getHinge), powered and open when
  a neighbour gives a signal; the room above must be free and the floor sturdy;
- chests and trapped chests: facing the player, joined to a single chest beside facing the same
  way (the type ``left``/``right``, the neighbour turning into the other half), or, sneaking, to
  the chest whose side was clicked (ChestBlock.getStateForPlacement, updateShape);
- torches (standing or on a wall: ``torch``, ``soul_torch``, ``redstone_torch``, ``copper_torch``)
  and signs (standing, rotated in 16 steps opposite the player, or on a wall), whichever fits first
  in the directions the player looks nearest, the clicked face's opposite first
  (StandingAndWallBlockItem.getPlacementState with BlockPlaceContext.getNearestLookingDirections);
  banners (the sign's rules: BannerBlock, WallBannerBlock) and heads and skulls (standing anywhere,
  turned with the player; on a wall before the first block that is not replaceable; powered by a
  neighbour's signal);
- hanging signs: under a sturdy block (square to the player, or attached and turned in 16 steps
  when sneaking: CeilingHangingSignBlock) or on a wall held by a sturdy block beside
  (WallHangingSignBlock.canPlace); under another hanging sign is not modelled;
- rails: straight along the player's direction on a sturdy block (BaseRailBlock), then joined to
  the rails round it (RailState: :mod:`emulator.world.rails`).

- ``state_for_placement(ctx) -> (block_id, properties) | None | NotImplemented``: NotImplemented
  for a block none of these rules covers; None when the block cannot be placed there.
- ``after_placed(state, pos, block_id, properties)``: the door's upper half, the chest's partner,
  the rails joined,
  the sign's block entity (its empty text; the editor the game opens for the player is not
  observable by a pack).
- ``replaceable_by(state, block, ctx)``: a block the placed item goes into (BlockBehaviour.canBeReplaced).

Sources (decompiled 1.21.x): world/level/block/SlabBlock.java, DoorBlock.java, ChestBlock.java,
TorchBlock.java and BaseTorchBlock.canSurvive, WallTorchBlock.java, StandingSignBlock.java,
WallSignBlock.java, CeilingHangingSignBlock, WallHangingSignBlock, BannerBlock, WallBannerBlock,
SkullBlock, AbstractSkullBlock, WallSkullBlock, BaseRailBlock, world/item/HangingSignItem.java, world/item/StandingAndWallBlockItem.java, world/item/context/BlockPlaceContext.java,
util/SegmentedAnglePrecision.java (fromDegrees: Math.round(deg * 16 / 360) & 15).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from emulator.world import block_shapes, command_blocks, rails, signs
from emulator.world.blocks import BlockState
from emulator.world.errors import Unmodelled
from emulator.world.placed_states import (AXIS, CLOCKWISE, HORIZONTAL, OFFSETS, OPPOSITE, horizontal_direction,
                                          ordered_by_nearest)

_TORCHES = {"minecraft:torch": "minecraft:wall_torch", "minecraft:soul_torch": "minecraft:soul_wall_torch",
            "minecraft:redstone_torch": "minecraft:redstone_wall_torch",
            "minecraft:copper_torch": "minecraft:copper_wall_torch"}
_CHESTS = ("minecraft:chest", "minecraft:trapped_chest")
_SKULLS = ("_skull", "_head")


@dataclass
class PlaceContext:
    """What BlockPlaceContext gives a block: where it goes, the click, the player, the item."""
    state: object
    player: object
    block_id: str  # the item's block
    target: tuple  # getClickedPos
    face: str  # getClickedFace
    hit: tuple  # getClickLocation
    replace_clicked: bool  # replacingClickedOnBlock
    build_top: int  # the level's maximum build height

    @property
    def water(self) -> bool:
        return self.state.blocks.get(self.target).id == "minecraft:water"

    def at(self, pos, direction: str, up: int = 0):
        dx, dy, dz = OFFSETS[direction]
        return (pos[0] + dx, pos[1] + dy + up, pos[2] + dz)

    def block(self, pos):
        return self.state.blocks.get(pos)


def replaceable_by(ctx: PlaceContext, block) -> bool:
    """SlabBlock.canBeReplaced: a single slab of the placed item, on its open side."""
    if block.id != ctx.block_id or not block.id.endswith("_slab"):
        return False
    kind = dict(block.properties).get("type", "bottom")
    if kind == "double":
        return False
    if not ctx.replace_clicked:
        return True
    upper = ctx.hit[1] - ctx.target[1] > 0.5
    if kind == "bottom":
        return ctx.face == "up" or upper and ctx.face not in ("up", "down")
    return ctx.face == "down" or not upper and ctx.face not in ("up", "down")


def state_for_placement(ctx: PlaceContext):
    block_id = ctx.block_id
    if block_id.endswith("_slab"):
        return block_id, _slab(ctx)
    if block_id.endswith("_door"):
        return _door(ctx)
    if block_id in _CHESTS:
        return block_id, _chest(ctx)
    if block_id in _TORCHES:
        return _standing_or_wall(ctx, block_id, _TORCHES[block_id], _torch_survives)
    if block_id.endswith("_hanging_sign"):
        return _hanging_sign(ctx, block_id, block_id.removesuffix("_hanging_sign") + "_wall_hanging_sign")
    if block_id.endswith("_sign"):
        return _standing_or_wall(ctx, block_id, block_id.removesuffix("_sign") + "_wall_sign", _sign_survives)
    if block_id.endswith("_banner"):
        return _standing_or_wall(ctx, block_id, block_id.removesuffix("_banner") + "_wall_banner", _sign_survives)
    if block_id.endswith(_SKULLS) and block_id != "minecraft:piston_head":
        kind = "_skull" if block_id.endswith("_skull") else "_head"
        return _standing_or_wall(ctx, block_id, block_id.removesuffix(kind) + "_wall" + kind, _skull_survives)
    if block_id in rails.RAILS:
        return _rail(ctx, block_id)
    return NotImplemented


def after_placed(state, pos, block_id: str, properties: dict) -> None:
    if block_id.endswith("_sign"):
        state.blocks.entities[tuple(pos)] = signs.new_entity(state.version)
    elif block_id.endswith("_door"):  # DoorBlock.setPlacedBy
        upper = (pos[0], pos[1] + 1, pos[2])
        state.blocks.set_state(upper, BlockState(block_id, _sorted({**properties, "half": "upper"})))
    elif block_id in _CHESTS and properties.get("type") != "single":
        _join_partner(state, pos, block_id, properties)
    elif block_id in rails.RAILS:  # BaseRailBlock.onPlace
        rails.join(state.blocks, pos, command_blocks.has_neighbour_signal(state, pos))


def _sorted(properties: dict) -> tuple:
    return tuple(sorted(properties.items()))


# ---------------------------------------------------------------------- slabs
def _slab(ctx: PlaceContext) -> dict:
    there = ctx.block(ctx.target)
    if there.id == ctx.block_id:
        return {"type": "double", "waterlogged": "false"}
    top = ctx.face == "down" or (ctx.face != "up" and ctx.hit[1] - ctx.target[1] > 0.5)
    return {"type": "top" if top else "bottom", "waterlogged": "true" if ctx.water else "false"}


# ---------------------------------------------------------------------- doors
def _door(ctx: PlaceContext):
    pos = ctx.target
    above = (pos[0], pos[1] + 1, pos[2])
    room = ctx.block(above)
    if pos[1] >= ctx.build_top - 1 or not (room.id in block_shapes.REPLACEABLE or replaceable_by(ctx, room)):
        return None
    if not block_shapes.is_face_sturdy(ctx.block((pos[0], pos[1] - 1, pos[2]))):  # DoorBlock.canSurvive
        return None
    powered = command_blocks.has_neighbour_signal(ctx.state, pos) or command_blocks.has_neighbour_signal(ctx.state,
                                                                                                         above)
    flag = "true" if powered else "false"
    facing = horizontal_direction(ctx.player)
    return ctx.block_id, {"facing": facing, "half": "lower", "hinge": _hinge(ctx, facing), "open": flag,
                          "powered": flag}


def _hinge(ctx: PlaceContext, facing: str) -> str:
    """DoorBlock.getHinge."""
    pos, left, right = ctx.target, _COUNTER_CLOCKWISE[facing], CLOCKWISE[facing]
    full = [block_shapes.is_collision_full(ctx.block(ctx.at(pos, side, up)))
            for side in (left, right) for up in (0, 1)]
    side_score = -full[0] - full[1] + full[2] + full[3]
    left_door, right_door = (_lower_door(ctx.block(ctx.at(pos, side))) for side in (left, right))
    if (left_door and not right_door) or side_score > 0:
        return "right"
    if (right_door and not left_door) or side_score < 0:
        return "left"
    step_x, _, step_z = OFFSETS[facing]
    dx, dz = ctx.hit[0] - pos[0], ctx.hit[2] - pos[2]
    left_hinge = ((step_x >= 0 or not dz < 0.5) and (step_x <= 0 or not dz > 0.5)
                  and (step_z >= 0 or not dx > 0.5) and (step_z <= 0 or not dx < 0.5))
    return "left" if left_hinge else "right"


def _lower_door(block) -> bool:
    return block.id.endswith("_door") and dict(block.properties).get("half") == "lower"


_COUNTER_CLOCKWISE = {v: k for k, v in CLOCKWISE.items()}


# ---------------------------------------------------------------------- chests
def _chest(ctx: PlaceContext) -> dict:
    """ChestBlock.getStateForPlacement."""
    kind, facing = "single", OPPOSITE[horizontal_direction(ctx.player)]
    sneaking = ctx.player.sneaking
    if ctx.face in CLOCKWISE and sneaking:
        partner = _partner_facing(ctx, OPPOSITE[ctx.face])
        if partner is not None and _axis(partner) != _axis(ctx.face):
            facing = partner
            kind = "right" if _COUNTER_CLOCKWISE[partner] == OPPOSITE[ctx.face] else "left"
    if kind == "single" and not sneaking:
        if facing == _partner_facing(ctx, CLOCKWISE[facing]):
            kind = "left"
        elif facing == _partner_facing(ctx, _COUNTER_CLOCKWISE[facing]):
            kind = "right"
    return {"facing": facing, "type": kind, "waterlogged": "true" if ctx.water else "false"}


def _axis(direction: str) -> str:
    return "x" if direction in ("east", "west") else "z"


def _partner_facing(ctx: PlaceContext, direction: str) -> str | None:
    """ChestBlock.candidatePartnerFacing: the facing of a single chest of the same kind there."""
    there = ctx.block(ctx.at(ctx.target, direction))
    properties = dict(there.properties)
    if there.id != ctx.block_id or properties.get("type", "single") != "single":
        return None
    if "facing" not in properties:
        raise Unmodelled(f"the default facing of the neighbouring {there.id} (placing a chest beside it reads it)")
    return properties["facing"]


def _join_partner(state, pos, block_id: str, properties: dict) -> None:
    """ChestBlock.updateShape of the chest the new one joined: the other half."""
    facing = properties["facing"]
    towards = CLOCKWISE[facing] if properties["type"] == "left" else _COUNTER_CLOCKWISE[facing]
    dx, dy, dz = OFFSETS[towards]
    partner_pos = (pos[0] + dx, pos[1] + dy, pos[2] + dz)
    partner = state.blocks.get(partner_pos)
    other = "right" if properties["type"] == "left" else "left"
    state.blocks.set_state(partner_pos, BlockState(partner.id, _sorted({**dict(partner.properties), "type": other})))


# ---------------------------------------------------------------------- torches and signs
def _standing_or_wall(ctx: PlaceContext, standing: str, wall: str, survives):
    """StandingAndWallBlockItem.getPlacementState (attached downwards): the first of the directions
    the player looks nearest (never up) whose block can stay there."""
    wall_state = _wall_state(ctx, wall, survives)
    for direction in nearest_looking_directions(ctx):
        if direction == "up":
            continue
        if direction == "down":
            placed = (standing, _standing_properties(ctx, standing))
            if survives(ctx, standing, placed[1]):
                return placed
        elif wall_state is not None:
            return wall, wall_state
    return None


def _standing_properties(ctx: PlaceContext, block_id: str) -> dict:
    if block_id.endswith("_sign"):  # StandingSignBlock: RotationSegment.convertToSegment(yRot + 180)
        return {"rotation": str(_segment(ctx.player.yaw + 180.0)), "waterlogged": "true" if ctx.water else "false"}
    if block_id.endswith("_banner"):  # BannerBlock: the same turn, no water
        return {"rotation": str(_segment(ctx.player.yaw + 180.0))}
    if block_id.endswith(_SKULLS):  # SkullBlock: convertToSegment(yRot), powered by a neighbour's signal
        return {"rotation": str(_segment(ctx.player.yaw)), "powered": _powered(ctx)}
    return {"lit": "true"} if block_id == "minecraft:redstone_torch" else {}


def _powered(ctx: PlaceContext) -> str:
    """AbstractSkullBlock.getStateForPlacement: Level.hasNeighborSignal."""
    return "true" if command_blocks.has_neighbour_signal(ctx.state, ctx.target) else "false"


def _segment(degrees) -> int:
    """SegmentedAnglePrecision(4).fromDegrees: Math.round(degrees * (16 / 360)) & 15, in floats."""
    value = np.float32(np.float32(degrees) * (np.float32(16) / np.float32(360)))
    return int(np.floor(np.float64(value) + 0.5)) & 15


def _wall_state(ctx: PlaceContext, wall: str, survives) -> dict | None:
    """WallTorchBlock / WallSignBlock.getStateForPlacement: facing away from the first horizontal
    direction (nearest first) whose block holds it."""
    for direction in nearest_looking_directions(ctx):
        if direction in ("up", "down"):
            continue
        properties = {"facing": OPPOSITE[direction]}
        if wall.endswith("_sign"):
            properties["waterlogged"] = "true" if ctx.water else "false"
        elif wall == "minecraft:redstone_wall_torch":
            properties["lit"] = "true"
        elif wall.endswith(_SKULLS):
            properties["powered"] = _powered(ctx)
        if survives(ctx, wall, properties):
            return properties
    return None


def nearest_looking_directions(ctx: PlaceContext) -> list[str]:
    """BlockPlaceContext.getNearestLookingDirections: when the clicked block is not replaced, the
    clicked face's opposite comes first."""
    directions = ordered_by_nearest(ctx.player)
    if not ctx.replace_clicked:
        first = OPPOSITE[ctx.face]
        directions = [first] + [d for d in directions if d != first]
    return directions


def _torch_survives(ctx: PlaceContext, block_id: str, properties: dict) -> bool:
    """BaseTorchBlock (canSupportCenter of the block below) / WallTorchBlock (a sturdy face behind)."""
    below_or_behind = OPPOSITE[properties["facing"]] if "facing" in properties else "down"
    return block_shapes.is_face_sturdy(ctx.block(ctx.at(ctx.target, below_or_behind)))


def _sign_survives(ctx: PlaceContext, block_id: str, properties: dict) -> bool:
    """StandingSignBlock / WallSignBlock and BannerBlock / WallBannerBlock.canSurvive: a solid block
    below or behind."""
    below_or_behind = OPPOSITE[properties["facing"]] if "facing" in properties else "down"
    return block_shapes.is_solid(ctx.block(ctx.at(ctx.target, below_or_behind)))


def _skull_survives(ctx: PlaceContext, block_id: str, properties: dict) -> bool:
    """A standing skull survives anywhere; WallSkullBlock.getStateForPlacement takes the first
    horizontal direction whose block is not replaceable."""
    if "facing" not in properties:
        return True
    return ctx.block(ctx.at(ctx.target, OPPOSITE[properties["facing"]])).id not in block_shapes.REPLACEABLE


# ---------------------------------------------------------------------- hanging signs
def _hanging_sign(ctx: PlaceContext, ceiling: str, wall: str):
    """HangingSignItem (StandingAndWallBlockItem attached upwards): the nearest looking direction
    up gives the ceiling sign, a horizontal one the wall sign, whichever can be placed first."""
    wall_state = _wall_hanging_state(ctx, wall)
    for direction in nearest_looking_directions(ctx):
        if direction == "down":
            continue
        if direction == "up":
            properties = _ceiling_hanging_state(ctx)
            if properties is not None:
                return ceiling, properties
        elif wall_state is not None:
            return wall, wall_state
    return None


def _ceiling_hanging_state(ctx: PlaceContext) -> dict | None:
    """CeilingHangingSignBlock.getStateForPlacement and canSurvive (a sturdy block above): attached
    (turned in 16 steps opposite the player) unless the face above is full and the player stands
    upright, else square to the player's direction."""
    above = ctx.block(ctx.at(ctx.target, "up"))
    if above.id.endswith("_hanging_sign"):
        raise Unmodelled(f"placing a hanging sign under {above.id}")
    if not block_shapes.is_face_sturdy(above):
        return None
    attached = ctx.player.sneaking
    rotation = _segment(ctx.player.yaw + 180.0) if attached else \
        _SEGMENT_OF[OPPOSITE[horizontal_direction(ctx.player)]]
    return {"attached": "true" if attached else "false", "rotation": str(rotation),
            "waterlogged": "true" if ctx.water else "false"}


_SEGMENT_OF = {"south": 0, "west": 4, "north": 8, "east": 12}  # RotationSegment.convertToSegment(Direction)


def _wall_hanging_state(ctx: PlaceContext, wall: str) -> dict | None:
    """WallHangingSignBlock.getStateForPlacement: the first horizontal direction off the clicked
    face's axis, facing away from it, held by a sturdy block (or a wall hanging sign along the same
    axis) on either side (canPlace, canAttachTo)."""
    for direction in nearest_looking_directions(ctx):
        if direction in ("up", "down") or AXIS[direction] == AXIS[ctx.face]:
            continue
        facing = OPPOSITE[direction]
        sides = (CLOCKWISE[facing], _COUNTER_CLOCKWISE[facing])
        if any(_holds_hanging_sign(ctx, ctx.block(ctx.at(ctx.target, side)), facing) for side in sides):
            return {"facing": facing, "waterlogged": "true" if ctx.water else "false"}
    return None


def _holds_hanging_sign(ctx: PlaceContext, block, facing: str) -> bool:
    if block.id.endswith("_wall_hanging_sign"):
        return AXIS[dict(block.properties).get("facing", "north")] == AXIS[facing]
    return block_shapes.is_face_sturdy(block)


# ---------------------------------------------------------------------- rails
def _rail(ctx: PlaceContext, block_id: str):
    """BaseRailBlock.getStateForPlacement and canSurvive (a sturdy block below): straight along the
    player's direction (then joined to the rails round it: :mod:`emulator.world.rails`). A powered,
    detector or activator rail next to a signal is not modelled."""
    if not block_shapes.is_face_sturdy(ctx.block(ctx.at(ctx.target, "down"))):
        return None
    facing = horizontal_direction(ctx.player)
    properties = {"shape": "east_west" if facing in ("east", "west") else "north_south",
                  "waterlogged": "true" if ctx.water else "false"}
    if block_id != "minecraft:rail":
        if command_blocks.has_neighbour_signal(ctx.state, ctx.target):
            raise Unmodelled(f"placing {block_id} next to a redstone signal (its power along the line)")
        properties["powered"] = "false"
    return block_id, properties
