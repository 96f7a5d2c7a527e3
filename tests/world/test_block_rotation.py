"""Block states, positions and yaws turned and mirrored as ``place template`` turns them (decompiled
26.1.2, the same in 1.16.5: Rotation, Mirror, StructureTemplate.transform, Entity.rotate/mirror and
each block class's rotate and mirror, named per case)."""
import numpy as np
import pytest

from emulator.world.block_rotation import turned_entity_pos, turned_pos, turned_state, turned_yaw
from emulator.world.blocks import BlockSpec

NONE, CW, HALF, CCW = 0, 1, 2, 3
LEFT_RIGHT, FRONT_BACK = 1, 2


def turned(block: str, props: dict, mirror: int = 0, rotation: int = 0) -> dict:
    spec = BlockSpec("minecraft:" + block, False, tuple(sorted(props.items())), None)
    return dict(turned_state(spec, mirror, rotation).properties)


@pytest.mark.parametrize("block, props, mirror, rotation, expected", [
    # HorizontalDirectionalBlock: rotate the facing; mirror = rotate by Mirror.getRotation(facing)
    ("furnace", {"facing": "north"}, 0, CW, {"facing": "east"}),
    ("furnace", {"facing": "north"}, LEFT_RIGHT, 0, {"facing": "south"}),
    ("furnace", {"facing": "north"}, FRONT_BACK, 0, {"facing": "north"}),
    ("observer", {"facing": "up"}, LEFT_RIGHT, CW, {"facing": "up"}),  # up and down stay
    ("anvil", {"facing": "north"}, LEFT_RIGHT, 0, {"facing": "north"}),  # AnvilBlock: no mirror
    ("anvil", {"facing": "north"}, 0, CCW, {"facing": "west"}),
    # 16 steps: Rotation.rotate(r, 16), Mirror.mirror(r, 16)
    ("oak_sign", {"rotation": "1"}, 0, CW, {"rotation": "5"}),
    ("oak_sign", {"rotation": "14"}, 0, HALF, {"rotation": "6"}),
    ("oak_sign", {"rotation": "1"}, LEFT_RIGHT, 0, {"rotation": "7"}),
    ("oak_sign", {"rotation": "1"}, FRONT_BACK, 0, {"rotation": "15"}),
    ("oak_sign", {"rotation": "12"}, LEFT_RIGHT, 0, {"rotation": "12"}),
    # RotatedPillarBlock.rotatePillar
    ("oak_log", {"axis": "x"}, 0, CW, {"axis": "z"}),
    ("oak_log", {"axis": "y"}, 0, CW, {"axis": "y"}),
    ("oak_log", {"axis": "x"}, FRONT_BACK, HALF, {"axis": "x"}),
    # CrossCollisionBlock / WallBlock: each side's value moves with its side
    ("oak_fence", {"north": "true", "east": "false", "south": "false", "west": "false"}, 0, CW,
     {"north": "false", "east": "true", "south": "false", "west": "false"}),
    ("cobblestone_wall", {"north": "tall", "east": "low", "south": "none", "west": "none", "up": "true"},
     LEFT_RIGHT, 0, {"north": "none", "east": "low", "south": "tall", "west": "none", "up": "true"}),
    # HugeMushroomBlock: all six (up and down stay)
    ("red_mushroom_block", {"north": "true", "east": "false", "south": "false", "west": "false", "up": "true",
                            "down": "false"}, 0, CCW,
     {"north": "false", "east": "false", "south": "false", "west": "true", "up": "true", "down": "false"}),
    # StairBlock.mirror: across the facing's axis turned round with a corner's side swapped (FRONT_BACK
    # keeps an inner corner's); along it nothing changes
    ("oak_stairs", {"facing": "north", "shape": "outer_left"}, LEFT_RIGHT, 0, {"facing": "south", "shape": "outer_right"}),
    ("oak_stairs", {"facing": "north", "shape": "inner_left"}, LEFT_RIGHT, 0, {"facing": "south", "shape": "inner_right"}),
    ("oak_stairs", {"facing": "east", "shape": "inner_left"}, FRONT_BACK, 0, {"facing": "west", "shape": "inner_left"}),
    ("oak_stairs", {"facing": "east", "shape": "outer_left"}, FRONT_BACK, 0, {"facing": "west", "shape": "outer_right"}),
    ("oak_stairs", {"facing": "east", "shape": "outer_left"}, LEFT_RIGHT, 0, {"facing": "east", "shape": "outer_left"}),
    ("oak_stairs", {"facing": "east", "shape": "outer_left"}, 0, CW, {"facing": "south", "shape": "outer_left"}),
    # DoorBlock.mirror: the hinge flips whatever the axis
    ("oak_door", {"facing": "east", "hinge": "left"}, LEFT_RIGHT, 0, {"facing": "east", "hinge": "right"}),
    ("oak_door", {"facing": "east", "hinge": "left"}, 0, CW, {"facing": "south", "hinge": "left"}),
    # BaseRailBlock.rotate / mirror
    ("rail", {"shape": "south_east"}, 0, CW, {"shape": "south_west"}),
    ("rail", {"shape": "north_south"}, 0, CCW, {"shape": "east_west"}),
    ("rail", {"shape": "ascending_east"}, 0, CW, {"shape": "ascending_south"}),
    ("rail", {"shape": "north_east"}, FRONT_BACK, 0, {"shape": "north_west"}),
    ("rail", {"shape": "ascending_north"}, LEFT_RIGHT, 0, {"shape": "ascending_south"}),
    # JigsawBlock / CrafterBlock: FrontAndTop, both turned
    ("jigsaw", {"orientation": "north_up"}, 0, CW, {"orientation": "east_up"}),
    ("crafter", {"orientation": "up_north"}, LEFT_RIGHT, 0, {"orientation": "up_south"}),
    # FireBlock and ChorusPlantBlock have no rotate of their own: their sides stay
    ("fire", {"north": "true", "east": "false", "south": "false", "west": "false", "up": "false"}, 0, CW,
     {"north": "true", "east": "false", "south": "false", "west": "false", "up": "false"}),
])
def test_block_states(block, props, mirror, rotation, expected):
    assert turned(block, props, mirror, rotation) == expected


def test_positions_about_the_corner():
    # StructureTemplate.transform(BlockPos) and (Vec3): a quarter turn clockwise (x, z) -> (-z, x)
    assert [turned_pos((1, 2, 3), 0, r) for r in range(4)] == [(1, 2, 3), (-3, 2, 1), (-1, 2, -3), (3, 2, -1)]
    assert turned_pos((1, 2, 3), LEFT_RIGHT, 0) == (1, 2, -3) and turned_pos((1, 2, 3), FRONT_BACK, CW) == (-3, 2, -1)
    assert turned_entity_pos((1.5, 2.0, 0.25), 0, CW) == (0.75, 2.0, 1.5)
    assert turned_entity_pos((1.5, 2.0, 0.25), LEFT_RIGHT, 0) == (1.5, 2.0, 0.75)


def test_yaws():
    # Entity.rotate + Entity.mirror - yRot, from Mth.wrapDegrees of the yaw
    assert turned_yaw(0.0, 0, CW) == np.float32(90.0)
    assert turned_yaw(350.0, 0, CW) == np.float32(-280.0)  # -10 + 90, plus -10 (no mirror), less 350
    assert turned_yaw(30.0, LEFT_RIGHT, 0) == np.float32(150.0)
    assert turned_yaw(30.0, FRONT_BACK, 0) == np.float32(-30.0)
