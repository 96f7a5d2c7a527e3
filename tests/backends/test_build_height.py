"""Every command that reads a block position (setblock, fill, fillbiome, clone, place, data and
execute on blocks, item and loot with a block) fails when it runs outside the level's build height
or the world's border, "That position is out of this world!" (BlockPosArgument.getLoadedBlockPos: Level.isInWorldBounds,
isOutsideBuildHeight and isInWorldBoundsHorizontal), on both backends; the function still loads
(the positions parse: BlockPosArgument.parse reads any integer), so ``dpemu check`` accepts them."""
from __future__ import annotations

import json
from types import SimpleNamespace

import pytest

from emulator.commands.blocks import in_world
from emulator.commands.entities import new_state
from emulator.commands.env import Env
from emulator.world.dimensions import Levels
from emulator.world.errors import CommandFailure, Unmodelled
from mcfunction_parser.parse import parse_function
from tests.backends.test_dimensions import FLAT, pack, run_both, score
from tests.commands.test_data import run

# (holder, command, succeeds): the overworld's build height is -64 – 319 (BuiltinDimensionTypes:
# min_y -64, height 384), the nether's and the end's 0 – 255, x and z in [-30,000,000, 30,000,000)
CASES = [
    ("#top", "setblock 0 319 0 stone", True),
    ("#above", "setblock 0 320 0 stone", False),
    ("#bottom", "setblock 0 -64 0 stone", True),
    ("#below", "setblock 0 -65 0 stone", False),
    ("#border", "setblock 29999999 0 -30000000 stone", True),
    ("#past", "setblock 30000000 0 0 stone", False),
    ("#fill", "fill 0 318 0 1 319 1 stone", True),
    ("#fill_over", "fill 0 319 0 1 320 1 stone", False),
    ("#biome", "fillbiome 0 -64 0 3 319 3 minecraft:desert", True),
    ("#biome_over", "fillbiome 0 -64 0 3 320 3 minecraft:desert", False),
    ("#nether", "execute in minecraft:the_nether run setblock 0 255 0 stone", True),
    ("#nether_over", "execute in minecraft:the_nether run setblock 0 256 0 stone", False),
    ("#nether_low", "execute in minecraft:the_nether run setblock 0 -1 0 stone", False),
    ("#shallow", "execute in t:shallow run setblock 0 79 0 stone", True),
    ("#shallow_over", "execute in t:shallow run setblock 0 80 0 stone", False),
    # ExecuteCommand's conditions read their positions by BlockPosArgument.getLoadedBlockPos too
    ("#unless_block_over", "execute unless block 9 320 9 stone", False),  # a failure, not a false test
    ("#if_blocks", "execute if blocks 9 0 9 9 0 9 9 319 9 all", True),
    ("#if_blocks_over", "execute if blocks 9 0 9 9 0 9 9 320 9 all", False),
    ("#if_biome", "execute if biome 1 -64 1 minecraft:desert", True),
    ("#if_biome_over", "execute if biome 1 -65 1 minecraft:desert", False),
    # ExecuteCommand.isChunkLoaded reads its position unchecked (getBlockPos); every chunk is loaded
    # here, so a column inside the world's border is, at any height
    ("#loaded", "execute if loaded 29999999 1000 -30000000", True),
    ("#loaded_past", "execute if loaded 30000000 0 0", False),
    ("#loaded_stage", "execute if loaded ~ ~ ~ run scoreboard players get #top v", True),
    ("#clone", "clone 0 0 0 1 1 1 5 318 5", True),
    ("#clone_over", "clone 0 0 0 1 1 1 5 320 5", False),
    ("#clone_from", "clone 0 319 0 0 320 0 5 5 5", False),
]


def _pack(tmp_path):
    main = "".join(f"execute store success score {holder} v run {command}\n" for holder, command, _ in CASES)
    root = pack(tmp_path, main)
    for name, body in (("dimension/shallow", {"type": "t:shallow_type", "generator": FLAT}),
                       ("dimension_type/shallow_type", {"min_y": 16, "height": 64, "coordinate_scale": 1.0})):
        (root / "data/t" / f"{name}.json").parent.mkdir(parents=True, exist_ok=True)
        (root / "data/t" / f"{name}.json").write_text(json.dumps(body))
    return root


def test_positions_outside_the_world_fail_when_run(tmp_path):
    emu = run_both(_pack(tmp_path))
    assert {holder: score(emu, holder) for holder, _, _ in CASES} == {h: ok if ok is None else int(ok) for h, _, ok in CASES}
    assert not emu.diagnostics  # a command's failure, as the game's: no error of the emulator's


@pytest.mark.parametrize("command", [
    "data get block 9 320 9",  # BlockDataAccessor, which `execute store … block` builds as well
    "item replace block 9 320 9 container.0 with minecraft:stone",  # ItemCommands
    "loot spawn 0 0 0 mine 9 320 9",  # LootCommand
    "place template t:none 9 320 9",  # PlaceCommand: the position is read before the template
])
def test_the_other_block_readers_fail_with_the_games_message(command):
    # each of these fails on an empty column anyway: the message tells the position check apart
    with pytest.raises(CommandFailure, match="That position is out of this world!"):
        run(Env(new_state(), {}, set()), command)


def test_the_check_accepts_them():
    text = "".join(command + "\n" for _, command, _ in CASES)
    _, diagnostics = parse_function(text, "f.mcfunction", "t:f", (1, 21, 0))
    assert not diagnostics


def _state(levels, version):
    """What in_world reads of the world: its levels and release."""
    return SimpleNamespace(version=version, entities=SimpleNamespace(table=SimpleNamespace(levels=levels)))


def test_the_message_and_the_heights_before_1_18():
    overworld = "minecraft:overworld"
    with pytest.raises(CommandFailure, match="That position is out of this world!"):
        in_world(_state(Levels(), (1, 21, 0)), overworld, (0, 320, 0))
    # before 1.18 every vanilla level's build height was 0 – 255
    in_world(_state(Levels(), (1, 17, 1)), overworld, (0, 255, 0))
    with pytest.raises(CommandFailure):
        in_world(_state(Levels(), (1, 17, 1)), overworld, (0, -1, 0))
    # a dimension type that does not give its build height: not modelled, said so
    with pytest.raises(Unmodelled, match="build height of t:odd"):
        in_world(_state(Levels.from_packs({"t:odd": {"type": {"coordinate_scale": 1.0}}}, {}), (1, 21, 0)),
                 "t:odd", (0, 0, 0))
