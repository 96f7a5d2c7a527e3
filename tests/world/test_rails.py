"""Rails joining their neighbours when placed (emulator.world.rails; RailState.place and connectTo,
decompiled 1.21)."""
import pytest

from emulator.world import rails
from emulator.world.blocks import BlockMap, BlockSpec, BlockState


def rail(blocks, pos, block_id="minecraft:rail", shape="north_south"):
    """A rail set without onPlace, on stone (a rail needs a sturdy block under it)."""
    blocks.setblock((pos[0], pos[1] - 1, pos[2]), BlockSpec("minecraft:stone", False, (), None))
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


def _emulator(tmp_path, functions):
    from emulator import Emulator
    from tests.conftest import write_pack
    root = write_pack(tmp_path / "pack", {f"demo/function/{name}.mcfunction": text for name, text in functions.items()})
    emu = Emulator(backend="python")
    emu.load([root])
    return emu


def test_setblock_joins_a_rail(tmp_path):
    # SetBlockCommand places with flag 2, which still runs Block.onPlace (BaseRailBlock.updateState)
    emu = _emulator(tmp_path, {"f": "fill 0 0 0 3 0 3 stone\nsetblock 0 1 0 rail\nsetblock 1 1 0 rail\n"})
    emu.call("demo:f")
    assert [shape(emu.state.blocks, (x, 1, 0)) for x in (0, 1)] == ["east_west", "east_west"]
    assert not any(d.unmodelled for d in emu.diagnostics)


def test_fill_places_rails_one_by_one_each_joining_those_before():
    # FillCommand.fillBlocks: BlockInput.place (setBlock flag 2) per position in BlockPos.betweenClosed
    # order (x fastest, then y, then z), each running BaseRailBlock.onPlace -> RailState.place, so a
    # fill of rails is a line of rails placed one after another
    from emulator.commands.blocks import _placed
    from types import SimpleNamespace
    blocks = BlockMap()
    blocks.fill((0, 0, 0), (3, 0, 1), BlockSpec("minecraft:stone", False, (), None))
    env = SimpleNamespace(state=SimpleNamespace(blocks_in=lambda d: blocks, level=lambda d: SimpleNamespace(blocks=blocks)))
    spec = BlockSpec("minecraft:rail", False, (), None)
    blocks.fill((0, 1, 0), (3, 1, 0), spec, on_placed=_placed(env, SimpleNamespace(dimension="o"), spec, "replace"))
    assert [shape(blocks, (x, 1, 0)) for x in range(4)] == ["east_west"] * 4
    # a 2x2 square: (0,0) alone north_south, (1,0) joins it east_west, (0,1) finds (0,0) with one end
    # free, so both turn: (0,0) to south_east and (0,1) north_south; (1,1) closes the square
    blocks = BlockMap()
    blocks.fill((0, 0, 0), (1, 0, 1), BlockSpec("minecraft:stone", False, (), None))
    blocks.fill((0, 1, 0), (1, 1, 1), spec, on_placed=_placed(env, SimpleNamespace(dimension="o"), spec, "replace"))
    got = {(x, z): shape(blocks, (x, 1, z)) for x in (0, 1) for z in (0, 1)}
    assert got == {(0, 0): "south_east", (1, 0): "south_west", (0, 1): "north_east", (1, 1): "north_west"}


def test_fill_joins_rails_in_the_command_and_a_rail_that_would_pop_off_is_not_modelled(tmp_path):
    emu = _emulator(tmp_path, {"f": "fill 0 0 0 3 0 0 stone\nfill 0 1 0 3 1 0 rail\n",
                               "g": "fill 5 1 0 7 1 0 rail\n", "h": "setblock 9 1 0 rail\nsetblock 10 1 0 rail\n"})
    emu.call("demo:f")
    assert [shape(emu.state.blocks, (x, 1, 0)) for x in range(4)] == ["east_west"] * 4
    assert not any(d.unmodelled for d in emu.diagnostics)
    # BaseRailBlock.neighborChanged -> shouldBeRemoved: rails over air told their neighbour changed pop
    # off (dropResources, removeBlock); the emulator does not drop them, so it says so
    for function in ("demo:g", "demo:h"):
        emu.diagnostics.clear()
        emu.call(function)
        assert any(d.unmodelled and "popping off" in d.message for d in emu.diagnostics), function
