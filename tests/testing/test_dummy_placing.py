"""Dummies placing blocks whose state follows the placement (emulator.world.placed_states): each
block's getStateForPlacement with the BlockPlaceContext of PackTest's ``use block POS [DIR]``
(DummyCommand.useBlock: the click at POS as written, BlockPos.containing(POS)). Sources:
LecternBlock, AnvilBlock, StairBlock (getStairsShape), RotatedPillarBlock, PistonBaseBlock,
ObserverBlock, HopperBlock, Direction.fromYRot / orderedByNearest."""
import pytest

from tests.testing.test_dummy_hands import run


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_lectern_faces_the_player(tmp_path, backend):
    """LecternBlock.getStateForPlacement: facing = the player's horizontal direction, opposite; the
    dummy spawns looking south (yaw 0), then turns west (yaw 90)."""
    result = run(tmp_path, "# @dummy\n" + (
        "scoreboard objectives add used minecraft.used:minecraft.lectern\n"
        "setblock ~2 ~ ~ stone\nsetblock ~2 ~ ~2 stone\n"
        "give @s lectern 2\n"
        "dummy @s use block ~2 ~ ~ up\n"
        "assert block ~2 ~1 ~ lectern[facing=north,has_book=false,powered=false]\n"
        "tp @s ~ ~ ~ 90 0\n"
        "dummy @s use block ~2 ~ ~2 up\n"
        "assert block ~2 ~1 ~2 lectern[facing=east]\n"
        "assert score @s used matches 2\n"
        "assert not items entity @s weapon.mainhand *\n"), backend=backend)
    assert result.status == "passed", result.report()


def test_logs_take_the_clicked_face_axis_and_anvils_turn_clockwise(tmp_path):
    result = run(tmp_path, "# @dummy\n" + (
        "setblock ~2 ~ ~ stone\n"
        "give @s oak_log 3\n"
        "dummy @s use block ~2 ~ ~ up\n"
        "assert block ~2 ~1 ~ oak_log[axis=y]\n"
        "dummy @s use block ~2 ~ ~ east\n"
        "assert block ~3 ~ ~ oak_log[axis=x]\n"
        "dummy @s use block ~2 ~ ~ north\n"
        "assert block ~2 ~ ~-1 oak_log[axis=z]\n"
        "item replace entity @s weapon.mainhand with anvil\n"
        "dummy @s use block ~2 ~1 ~ up\n"
        "assert block ~2 ~2 ~ anvil[facing=west]\n"))
    assert result.status == "passed", result.report()


def test_stairs_take_the_half_from_the_click_and_the_shape_from_their_neighbours(tmp_path):
    """StairBlock: facing = the player's direction (south); a side clicked above the middle gives
    the top half; a stair facing across behind the new one (in its facing) makes it an outer
    corner, one in front an inner corner; a stair beside takes its new shape (updateShape)."""
    result = run(tmp_path, "# @dummy\n" + (
        "setblock ~2 ~ ~ stone\nsetblock ~4 ~ ~ stone\n"
        "give @s oak_stairs 5\n"
        "dummy @s use block ~2 ~ ~ up\n"
        "assert block ~2 ~1 ~ oak_stairs[facing=south,half=bottom,shape=straight,waterlogged=false]\n"
        "dummy @s use block ~4.5 ~0.75 ~ west\n"
        "assert block ~3 ~ ~ oak_stairs[facing=south,half=top]\n"
        "setblock ~6 ~1 ~1 oak_stairs[facing=east,half=bottom,shape=straight]\n"
        "setblock ~6 ~ ~ stone\n"
        "dummy @s use block ~6 ~ ~ up\n"                 # behind it (south): an east-facing stair
        "assert block ~6 ~1 ~ oak_stairs[facing=south,shape=outer_left]\n"
        "setblock ~8 ~1 ~-1 oak_stairs[facing=east,half=bottom,shape=straight]\n"
        "setblock ~8 ~ ~ stone\n"
        "dummy @s use block ~8 ~ ~ up\n"                 # in front of it (north): an east-facing stair
        "assert block ~8 ~1 ~ oak_stairs[facing=south,shape=inner_left]\n"
        "setblock ~11 ~1 ~ oak_stairs[facing=east,half=bottom,shape=straight]\n"
        "setblock ~10 ~ ~ stone\n"
        "dummy @s use block ~10 ~ ~ up\n"                # the new stair is in front of the east-facing one
        "assert block ~10 ~1 ~ oak_stairs[shape=straight]\n"
        "assert block ~11 ~1 ~ oak_stairs[facing=east,shape=inner_right]\n"))
    assert result.status == "passed", result.report()


def test_pistons_observers_and_hoppers_follow_the_look_and_the_face(tmp_path):
    """PistonBaseBlock: opposite the nearest looking direction (looking down: facing up);
    ObserverBlock: the nearest looking direction; HopperBlock: opposite the clicked side."""
    result = run(tmp_path, "# @dummy\n" + (
        "setblock ~2 ~ ~ stone\n"
        "tp @s ~ ~ ~ 0 90\n"
        "give @s piston\n"
        "dummy @s use block ~2 ~ ~ up\n"
        "assert block ~2 ~1 ~ piston[facing=up,extended=false]\n"
        "item replace entity @s weapon.mainhand with observer\n"
        "dummy @s use block ~2 ~1 ~ up\n"
        "assert block ~2 ~2 ~ observer[facing=down,powered=false]\n"
        "item replace entity @s weapon.mainhand with hopper\n"
        "dummy @s use block ~2 ~ ~ east\n"
        "assert block ~3 ~ ~ hopper[facing=west,enabled=true]\n"))
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_campfire_faces_the_player_lit_and_signals_over_hay(tmp_path, backend):
    """CampfireBlock.getStateForPlacement: facing = the player's horizontal direction (not its
    opposite), lit unless placed in water (then waterlogged), signal_fire over a hay block."""
    result = run(tmp_path, "# @dummy\n" + (
        "setblock ~2 ~ ~ stone\nsetblock ~2 ~ ~2 hay_block\nsetblock ~-2 ~ ~ stone\nsetblock ~-2 ~1 ~ water\n"
        "give @s campfire 3\n"
        "dummy @s use block ~2 ~ ~ up\n"
        "assert block ~2 ~1 ~ campfire[facing=south,lit=true,signal_fire=false,waterlogged=false]\n"
        "tp @s ~ ~ ~ 90 0\n"
        "dummy @s use block ~2 ~ ~2 up\n"
        "assert block ~2 ~1 ~2 campfire[facing=west,lit=true,signal_fire=true]\n"
        "dummy @s use block ~-2 ~ ~ up\n"
        "assert block ~-2 ~1 ~ campfire[lit=false,waterlogged=true]\n"), backend=backend)
    assert result.status == "passed", result.report()
