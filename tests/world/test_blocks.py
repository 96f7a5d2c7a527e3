"""The block map: setblock, fill, execute if block(s), block data.

Sources (decompiled 1.21): server/commands/SetBlockCommand.java, FillCommand.java,
ExecuteCommand.java (checkRegions), commands/arguments/blocks/BlockPredicateArgument.java,
server/commands/data/BlockDataAccessor.java.
"""
from __future__ import annotations

import pytest

from mcfunction_parser import ast
from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.nbt import String
from emulator.world import nbt_ops
from emulator.world.blocks import BlockMap, BlockState, block_pos, parse_block
from emulator.world.errors import CommandFailure
from emulator.world.source import Source
from tests.world.world_paths import path

LOC = Loc("t.mcfunction", 1, 1)


def test_parse_block_specs():
    spec = parse_block("oak_stairs[half=top,facing=north]{CustomName:'\"x\"'}")
    assert spec.id == "minecraft:oak_stairs" and not spec.is_tag
    assert spec.properties == (("facing", "north"), ("half", "top"))
    assert spec.nbt == {"CustomName": '"x"'}
    assert parse_block("#minecraft:logs").is_tag
    with pytest.raises(ValueError):
        parse_block("stone]")


def test_setblock_fails_when_nothing_changes():
    # BlockInput.place returns false when the state is already there: "Could not set the block".
    world = BlockMap()
    assert world.setblock((0, 0, 0), parse_block("stone")) == 1
    with pytest.raises(CommandFailure, match="Could not set the block"):
        world.setblock((0, 0, 0), parse_block("stone"))
    with pytest.raises(CommandFailure, match="Could not set the block"):
        world.setblock((0, 0, 0), parse_block("dirt"), mode="keep")
    assert world.get((0, 0, 0)) == BlockState("minecraft:stone")
    assert world.get((5, 5, 5)).is_air


def test_fill_modes_and_counts():
    world = BlockMap()
    assert world.fill((0, 0, 0), (2, 2, 2), parse_block("stone")) == 27
    assert world.fill((0, 0, 0), (2, 2, 2), parse_block("glass"), mode="hollow") == 27  # centre becomes air
    assert world.get((1, 1, 1)).is_air and world.get((0, 1, 1)).id == "minecraft:glass"
    assert world.fill((0, 0, 0), (2, 2, 2), parse_block("dirt"), mode="keep") == 1
    assert world.fill((0, 0, 0), (2, 2, 2), parse_block("stone"), mode="outline") == 26
    stone = parse_block("stone")
    assert world.fill((0, 0, 0), (2, 2, 2), parse_block("gold_block"), filter=lambda p: world.test(p, stone)) == 26
    with pytest.raises(CommandFailure, match="No blocks were filled"):
        world.fill((0, 0, 0), (0, 0, 0), parse_block("gold_block"))
    with pytest.raises(CommandFailure) as err:
        world.fill((0, 0, 0), (32, 32, 31), parse_block("stone"))
    assert err.value.message == "Too many blocks in the specified area (maximum 32768, specified 34848)"  # 33 x 33 x 32


def test_if_block_predicates():
    world = BlockMap()
    world.setblock((0, 0, 0), parse_block("chest[facing=east,waterlogged=false]{Lock:\"k\",Items:[]}"))
    assert world.test((0, 0, 0), parse_block("chest"))
    assert world.test((0, 0, 0), parse_block("chest[facing=east]"))
    assert not world.test((0, 0, 0), parse_block("chest[facing=west]"))
    assert world.test((0, 0, 0), parse_block('chest{Lock:"k"}'))
    assert not world.test((0, 0, 0), parse_block('chest{Lock:"z"}'))
    assert not world.test((0, 0, 0), parse_block("#my:boxes"))
    assert world.test((0, 0, 0), parse_block("#my:boxes"), lambda tag, block: (tag, block) == ("my:boxes", "minecraft:chest"))


def test_if_blocks_counts_or_fails():
    world = BlockMap()
    world.setblock((0, 0, 0), parse_block("stone"))
    world.setblock((10, 0, 0), parse_block("stone"))
    # all: every block (air included) must match; masked skips air in the source region.
    assert world.compare_regions((0, 0, 0), (1, 0, 0), (10, 0, 0), masked=False) == 2
    world.setblock((11, 0, 0), parse_block("dirt"))
    assert world.compare_regions((0, 0, 0), (1, 0, 0), (10, 0, 0), masked=False) is None
    assert world.compare_regions((0, 0, 0), (1, 0, 0), (10, 0, 0), masked=True) == 1


def test_block_data_accessor():
    world = BlockMap()
    world.setblock((1, 2, 3), parse_block("barrel{Items:[]}"))
    nbt = world.block_nbt((1, 2, 3))
    assert nbt["x"] == 1 and nbt["z"] == 3 and nbt["id"] == "minecraft:barrel"
    world.modify_block((1, 2, 3), lambda n: nbt_ops.set_path(n, path("Lock", "Lock"), String("a")))
    assert world.entity((1, 2, 3)) == {"Items": [], "Lock": "a"}
    world.setblock((0, 0, 0), parse_block("stone"))
    with pytest.raises(CommandFailure, match="not a block entity"):
        world.block_nbt((0, 0, 0))


def test_block_positions_floor_without_centring():
    src = Source(pos=(0.5, 64.9, -0.5))
    vec = ast.Vec3(ast.Coord("rel", 0.0), ast.Coord("rel", 0.0), ast.Coord("abs", 3.0, True), LOC)
    assert block_pos(src, vec) == (0, 64, 3)
