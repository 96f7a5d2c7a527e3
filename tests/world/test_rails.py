"""Rails joining their neighbours when placed (emulator.world.rails; RailState.place and connectTo,
decompiled 1.21)."""
import pytest

from emulator.world import rails
from emulator.world.blocks import BlockMap, BlockSpec, BlockState


def rail(blocks, pos, block_id="minecraft:rail", shape="north_south"):
    blocks.setblock(pos, BlockSpec(block_id, False, (("shape", shape),), None))


def shape(blocks, pos):
    return dict(blocks.get(pos).properties)["shape"]


@pytest.mark.parametrize("powered,expected", [(False, "south_east"), (True, "north_west")])
def test_four_open_ways_pick_the_curve_by_power(powered, expected):
    # RailState.place: both axes open keeps the placed shape, then a plain rail takes a corner:
    # without power the last of NW, NE, SW, SE that is open, with power the last of SE, SW, NE, NW
    blocks = BlockMap()
    for pos in ((0, 0, -1), (0, 0, 1), (-1, 0, 0), (1, 0, 0)):
        rail(blocks, pos)
    rail(blocks, (0, 0, 0))
    rails.join(blocks, (0, 0, 0), powered)
    assert shape(blocks, (0, 0, 0)) == expected


def test_straight_rails_make_no_curve_and_a_rail_with_both_ends_taken_keeps_its_shape():
    blocks = BlockMap()
    rail(blocks, (0, 0, 1))
    rail(blocks, (1, 0, 0))
    rail(blocks, (0, 0, 0), "minecraft:powered_rail", "east_west")
    rails.join(blocks, (0, 0, 0))
    assert shape(blocks, (0, 0, 0)) == "east_west"  # both axes open: the placed shape
    # a line of three: the middle rail's ends both lead to rails, so a fourth beside it does not turn it
    blocks = BlockMap()
    for x in (0, 1, 2):
        rail(blocks, (x, 0, 0), shape="east_west")
    rail(blocks, (1, 0, 1))
    rails.join(blocks, (1, 0, 1))
    assert shape(blocks, (1, 0, 0)) == "east_west" and shape(blocks, (1, 0, 1)) == "north_south"
    assert blocks.get((1, 0, 1)) == BlockState("minecraft:rail", (("shape", "north_south"),))


def test_setblock_joins_a_rail_and_fill_says_it_does_not(tmp_path):
    # SetBlockCommand places with flag 2, which still runs Block.onPlace (BaseRailBlock.updateState)
    from emulator import Emulator
    from tests.conftest import write_pack
    root = write_pack(tmp_path / "pack", {"demo/function/f.mcfunction": "setblock 0 0 0 rail\nsetblock 1 0 0 rail\n",
                                          "demo/function/g.mcfunction": "fill 5 0 0 7 0 0 rail\n"})
    emu = Emulator(backend="python")
    emu.load([root])
    emu.call("demo:f")
    assert [shape(emu.state.blocks, (x, 0, 0)) for x in (0, 1)] == ["east_west", "east_west"]
    emu.call("demo:g")
    assert any(d.unmodelled and "fill" in d.message for d in emu.diagnostics)
