"""``data`` commands on storage, entities and blocks through their accessors (decompiled 1.21
server/commands/data/DataCommands.java, EntityDataAccessor.java, BlockDataAccessor.java,
StorageDataAccessor.java)."""
from __future__ import annotations

import pytest

from mcfunction_parser import ast
from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.parse import parse_command
from emulator.world import data_commands as dc
from emulator.world.blocks import parse_block
from emulator.world.errors import CommandFailure
from emulator.world.source import Source


def parsed(text: str):
    cmd, diagnostics = parse_command(text, Loc("t.mcfunction", 1, 1), (1, 21, 0))
    assert not diagnostics, diagnostics
    return cmd


def run(world: dc.World, text: str) -> int:
    """A small dispatcher over the data command nodes, as a backend would write it."""
    cmd = parsed(text)
    acc = dc.accessor(cmd.target, world)
    if isinstance(cmd, ast.DataGet):
        return dc.data_get(acc, cmd.path, cmd.scale)
    if isinstance(cmd, ast.DataMerge):
        return dc.data_merge(acc, cmd.nbt)
    if isinstance(cmd, ast.DataRemove):
        return dc.data_remove(acc, cmd.path)
    source = cmd.source
    if isinstance(source, ast.SourceValue):
        values = [source.value]
    elif isinstance(source, ast.SourceFrom):
        values = dc.source_values(dc.accessor(source.source, world), source.path)
    else:
        values = dc.string_values(dc.accessor(source.source, world), source.path, source.start, source.end)
    return dc.data_modify(acc, cmd.path, cmd.mode, cmd.index, values)


@pytest.fixture
def world():
    w = dc.World()
    w.entities.summon("minecraft:marker", (1.0, 2.0, 3.0))
    w.blocks.setblock((0, 0, 0), parse_block("chest{Items:[]}"))
    w.blocks.setblock((1, 0, 0), parse_block("stone"))
    return w


def test_storage_entity_and_block_round_trip(world):
    assert run(world, "data modify storage pool:s pos set from entity @e[limit=1] Pos") == 1
    assert run(world, "data get storage pool:s pos[2] 10") == 30
    assert run(world, "data modify entity @e[limit=1] data.x set from storage pool:s pos[0]") == 1
    assert run(world, "data get entity @e[limit=1] data.x") == 1
    assert run(world, "data modify block 0 0 0 Lock set string storage pool:s pos[1] 0 1") == 1
    assert world.blocks.entity((0, 0, 0))["Lock"] == "2"
    assert run(world, "data merge entity @e[limit=1] {Tags:[\"ball\"]}") == 1
    assert world.entities.entities[0].tags == {"ball"}
    assert run(world, "data get block 0 0 0") == 1


def test_accessor_failures(world):
    with pytest.raises(CommandFailure, match="not a block entity"):
        run(world, "data get block 1 0 0")
    with pytest.raises(CommandFailure, match="No entity was found"):
        run(world, "data get entity @e[tag=missing,limit=1]")
    with pytest.raises(CommandFailure, match="Nothing changed"):
        run(world, "data merge entity @e[limit=1] {Air:300s}")
    world.entities.add_player("Steve", (0, 0, 0))
    world.source = Source(entity=world.entities.players()[0])
    with pytest.raises(CommandFailure, match="Unable to modify player data"):
        run(world, "data modify entity @s Pos[0] set value 5d")


def test_if_data_and_store(world):
    cmd = parsed("execute if data entity @e[limit=1] Pos[] run say hi")
    assert dc.if_data(dc.accessor(cmd.subcommands[0].source, world), cmd.subcommands[0].path) == 3
    store = parsed("execute store result entity @e[limit=1] Pos[1] double 0.5 run say hi").subcommands[0]
    assert dc.store_data(dc.accessor(store.target, world), store.path, store.type, 9, store.scale) == 1
    assert world.entities.entities[0].pos == (1.0, 4.5, 3.0)
    # BlockDataAccessor fails as soon as it is made (when the store stage runs) without a block entity.
    with pytest.raises(CommandFailure, match="not a block entity"):
        dc.accessor(parsed("execute store result block 1 0 0 x int 1 run say hi").subcommands[0].target, world)
