"""Turning and mirroring what a structure template places (``place template ... ROTATION MIRROR``):
block states, positions, entities.

- ``turned_state(spec, mirror, rotation)``: BlockState.mirror then rotate (StructureTemplate.
  placeInWorld), by the state's properties as the game's block classes turn them: ``facing``
  (HorizontalDirectionalBlock and the others that keep a direction; up and down stay; an anvil is
  turned but not mirrored: AnvilBlock has no mirror), ``rotation`` in 16 steps (signs, banners,
  heads: Rotation.rotate / Mirror.mirror of an int), ``axis`` (RotatedPillarBlock.rotatePillar and
  the nether portal: x and z swap on a quarter turn; a mirror keeps it), the four sides ``north``
  ... ``west`` (fences, panes, bars, walls, redstone wire, tripwire, vines, the pale moss carpet:
  each side's value moves with its side) and all six on mushroom blocks and lichen-like blocks
  (HugeMushroomBlock, MultifaceBlock), a rail's ``shape`` (BaseRailBlock: the directions in its
  name turned), ``orientation`` (jigsaws and crafters: FrontAndTop, front and top turned), stairs
  (StairBlock.mirror: across their facing's axis they turn round and a corner's left and right
  swap, but for FRONT_BACK an inner corner keeps its side; along it nothing changes) and doors (a
  mirror flips the hinge). Fire and chorus plants keep their sides (no rotate of their own).
- ``turned_pos(pos, mirror, rotation)`` / ``turned_entity_pos``: StructureTemplate.transform of a
  block position and of an entity's position, about the pivot 0 0 0.
- ``turned_yaw(yaw, mirror, rotation)``: Entity.rotate + Entity.mirror - yRot, in floats.

Rotation and mirror are the game's ordinals (Rotation: none, clockwise_90, 180,
counterclockwise_90; Mirror: none, left_right, front_back). Sources: decompiled 26.1.2 and 1.16.5
Rotation, Mirror, StructureTemplate.transform/placeEntities, Entity.rotate/mirror and the block
classes named above (their rotate and mirror).
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from emulator.world.blocks import BlockSpec

ROTATIONS = ("none", "clockwise_90", "180", "counterclockwise_90")  # as ``place template`` writes them
MIRRORS = ("none", "left_right", "front_back")
LEFT_RIGHT, FRONT_BACK = 1, 2
CLOCKWISE = ("north", "east", "south", "west")
SIDES = frozenset(CLOCKWISE)
OPPOSITE = {"north": "south", "south": "north", "east": "west", "west": "east", "up": "down", "down": "up"}
UNTURNED = frozenset({"minecraft:fire", "minecraft:chorus_plant"})  # sides, and no rotate of their own
UNMIRRORED = frozenset({"minecraft:anvil", "minecraft:chipped_anvil", "minecraft:damaged_anvil"})
RAIL_SHAPES = ("north_south", "east_west", "ascending_east", "ascending_west", "ascending_north",
               "ascending_south", "south_east", "south_west", "north_west", "north_east")
_SHAPE_SWAP = {"outer_left": "outer_right", "outer_right": "outer_left", "inner_left": "inner_right",
               "inner_right": "inner_left"}


def rotate_direction(direction: str, rotation: int) -> str:
    """Rotation.rotate(Direction): up and down stay."""
    if direction not in SIDES:
        return direction
    return CLOCKWISE[(CLOCKWISE.index(direction) + rotation) % 4]


def mirror_direction(direction: str, mirror: int) -> str:
    """Mirror.mirror(Direction): LEFT_RIGHT flips north and south, FRONT_BACK east and west."""
    if (mirror == LEFT_RIGHT and direction in ("north", "south")) or (
            mirror == FRONT_BACK and direction in ("east", "west")):
        return OPPOSITE[direction]
    return direction


def turned_state(spec: BlockSpec, mirror: int, rotation: int) -> BlockSpec:
    """``spec`` mirrored, then rotated."""
    if spec.id in UNTURNED or not spec.properties or (mirror == 0 and rotation == 0):
        return spec
    props = dict(spec.properties)
    if mirror:
        props = _mirrored(spec.id, props, mirror)
    if rotation:
        props = _rotated(props, rotation)
    return replace(spec, properties=tuple(sorted(props.items())))


def _rotated(props: dict, rotation: int) -> dict:
    turn = lambda d: rotate_direction(d, rotation)  # noqa: E731
    if "facing" in props:
        props["facing"] = turn(props["facing"])
    if "rotation" in props:
        props["rotation"] = str((int(props["rotation"]) + 4 * rotation) % 16)  # Rotation.rotate(r, 16)
    if "axis" in props and rotation % 2 and props["axis"] in ("x", "z"):
        props["axis"] = "z" if props["axis"] == "x" else "x"
    if "shape" in props and props["shape"] in RAIL_SHAPES:
        props["shape"] = _rail(props["shape"], turn)
    if "orientation" in props:
        props["orientation"] = "_".join(turn(d) for d in props["orientation"].split("_"))
    return _sides(props, turn)


def _mirrored(block_id: str, props: dict, mirror: int) -> dict:
    flip = lambda d: mirror_direction(d, mirror)  # noqa: E731
    facing = props.get("facing")
    if facing is not None and block_id not in UNMIRRORED:
        if block_id.endswith("_stairs"):
            return _stairs_mirrored(props, mirror)
        props["facing"] = flip(facing)
        if "hinge" in props:  # DoorBlock.mirror: the other side
            props["hinge"] = "right" if props["hinge"] == "left" else "left"
    if "rotation" in props:
        props["rotation"] = str(_mirror_rotation(int(props["rotation"]), mirror))
    if "shape" in props and props["shape"] in RAIL_SHAPES:
        props["shape"] = _rail(props["shape"], flip)
    if "orientation" in props:
        props["orientation"] = "_".join(flip(d) for d in props["orientation"].split("_"))
    return _sides(props, flip)


def _sides(props: dict, move) -> dict:
    """Each side property's value goes to the side ``move`` takes it to (CrossCollisionBlock,
    WallBlock, HugeMushroomBlock.rotate: setValue(rotate(NORTH), old NORTH) ...)."""
    sides = [d for d in (*CLOCKWISE, "up", "down") if d in props]
    if not any(d in SIDES for d in sides):
        return props
    moved = {move(d): props[d] for d in sides}
    return {**props, **moved}


def _stairs_mirrored(props: dict, mirror: int) -> dict:
    """StairBlock.mirror: only across the facing's axis (LEFT_RIGHT for north/south, FRONT_BACK for
    east/west): turned round, and a corner's side swapped, but FRONT_BACK keeps an inner corner's."""
    across = (mirror == LEFT_RIGHT) == (props["facing"] in ("north", "south"))
    if not across:
        return props
    props["facing"] = OPPOSITE[props["facing"]]
    shape = props.get("shape", "straight")
    if shape in _SHAPE_SWAP and not (mirror == FRONT_BACK and shape.startswith("inner")):
        props["shape"] = _SHAPE_SWAP[shape]
    return props


def _mirror_rotation(rotation: int, mirror: int, steps: int = 16) -> int:
    """Mirror.mirror(int, steps)."""
    half = steps // 2
    corrected = rotation - steps if rotation > half else rotation
    if mirror == LEFT_RIGHT:
        return (half - corrected + steps) % steps
    return (steps - corrected) % steps


def _rail(shape: str, move) -> str:
    """A rail shape with the directions in its name moved (BaseRailBlock.rotate / mirror)."""
    if shape.startswith("ascending_"):
        return "ascending_" + move(shape[10:])
    ends = {move(d) for d in shape.split("_")}
    return next(s for s in RAIL_SHAPES if not s.startswith("ascending_") and set(s.split("_")) == ends)


def turned_pos(pos, mirror: int, rotation: int) -> tuple[int, int, int]:
    """StructureTemplate.transform(BlockPos) about the pivot 0 0 0."""
    x, y, z = pos
    if mirror == LEFT_RIGHT:
        z = -z
    elif mirror == FRONT_BACK:
        x = -x
    return ((x, y, z), (-z, y, x), (-x, y, -z), (z, y, -x))[rotation]


def turned_entity_pos(pos, mirror: int, rotation: int) -> tuple[float, float, float]:
    """StructureTemplate.transform(Vec3) about the pivot 0 0 0: a block's far side is 1 on."""
    x, y, z = pos
    if mirror == LEFT_RIGHT:
        z = 1.0 - z
    elif mirror == FRONT_BACK:
        x = 1.0 - x
    return ((x, y, z), (1.0 - z, y, x), (1.0 - x, y, 1.0 - z), (z, y, 1.0 - x))[rotation]


def turned_yaw(yaw, mirror: int, rotation: int) -> np.float32:
    """placeEntities: Entity.rotate(rotation) + Entity.mirror(mirror) - yRot, each from the
    wrapped yaw, in floats."""
    f32 = np.float32
    wrapped = _wrap_degrees(f32(yaw))
    turned = wrapped + (f32(0.0), f32(90.0), f32(180.0), f32(270.0))[rotation]
    mirrored = (wrapped, f32(180.0) - wrapped, -wrapped)[mirror]
    return f32(f32(turned + mirrored) - f32(yaw))


def _wrap_degrees(angle: np.float32) -> np.float32:
    """Mth.wrapDegrees(float)."""
    f = np.float32(np.fmod(angle, np.float32(360.0)))
    if f >= np.float32(180.0):
        f = np.float32(f - np.float32(360.0))
    if f < np.float32(-180.0):
        f = np.float32(f + np.float32(360.0))
    return f
