"""``data`` commands on storage, entities and blocks through their accessors (decompiled 1.21
server/commands/data/DataCommands.java, EntityDataAccessor.java, BlockDataAccessor.java,
StorageDataAccessor.java)."""
from __future__ import annotations

import pytest

from emulator.commands import conditions, stores
from emulator.commands.dispatch import run_command
from emulator.commands.entities import entity_context, new_state
from emulator.commands.env import Env
from emulator.world.errors import CommandFailure
from emulator.world.blocks import parse_block
from emulator.world.context import Context
from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.parse import parse_command


def parsed(text: str):
    cmd, diagnostics = parse_command(text, Loc("t.mcfunction", 1, 1), (1, 21, 0))
    assert not diagnostics, diagnostics
    return cmd


def run(env: Env, text: str, ctx: Context | None = None) -> int:
    return run_command(env, parsed(text), ctx or Context())


@pytest.fixture
def world():
    env = Env(new_state(), {}, set())
    env.state.entities.summon("minecraft:marker", (1.0, 2.0, 3.0))
    env.state.blocks.setblock((0, 0, 0), parse_block("chest{Items:[]}"))
    env.state.blocks.setblock((1, 0, 0), parse_block("stone"))
    return env


def test_storage_entity_and_block_round_trip(world):
    assert run(world, "data modify storage pool:s pos set from entity @e[limit=1] Pos") == 1
    assert run(world, "data get storage pool:s pos[2] 10") == 30
    assert run(world, "data modify entity @e[limit=1] data.x set from storage pool:s pos[0]") == 1
    assert run(world, "data get entity @e[limit=1] data.x") == 1
    assert run(world, "data modify block 0 0 0 Lock set string storage pool:s pos[1] 0 1") == 1
    assert world.state.blocks.entity((0, 0, 0))["Lock"] == "2"
    assert run(world, "data merge entity @e[limit=1] {Tags:[\"ball\"]}") == 1
    assert world.state.entities.entities[0].tags == {"ball"}
    assert run(world, "data get block 0 0 0") == 1


def test_accessor_failures(world):
    with pytest.raises(CommandFailure, match="not a block entity"):
        run(world, "data get block 1 0 0")
    with pytest.raises(CommandFailure, match="No entity was found"):
        run(world, "data get entity @e[tag=missing,limit=1]")
    with pytest.raises(CommandFailure, match="Nothing changed"):
        run(world, "data merge entity @e[limit=1] {Air:300s}")
    steve = world.state.entities.add_player("Steve", (0, 0, 0))
    with pytest.raises(CommandFailure, match="Unable to modify player data"):
        run(world, "data modify entity @s Pos[0] set value 5d", entity_context(world.state, steve))


def test_if_data_and_store(world):
    cmd = parsed("execute if data entity @e[limit=1] Pos[] run say hi")
    assert conditions.count(world, cmd.subcommands[0], Context()) == 3
    store = parsed("execute store result entity @e[limit=1] Pos[1] double 0.5 run say hi").subcommands[0]
    stores.store(world, store, stores.store_target(world, store, Context()), True, 9)
    assert world.state.entities.entities[0].pos == (1.0, 4.5, 3.0)
    # BlockDataAccessor fails as soon as it is made (when the store stage runs) without a block entity.
    with pytest.raises(CommandFailure, match="not a block entity"):
        stores.store_target(world, parsed("execute store result block 1 0 0 x int 1 run say hi").subcommands[0],
                            Context())
