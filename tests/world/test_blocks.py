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
from emulator.world.blocks import BlockMap, BlockState, block_pos, parse_block, with_defaults
from emulator.world.errors import CommandFailure, Unmodelled
from emulator.world.loot_context import snbt_or_tag
from emulator.world.source import Source
from tests.world.world_emulator import emulator
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


# ---------------------------------------------------------------------- default states
@pytest.mark.parametrize("version", [(1, 13, 0), (1, 16, 5), (1, 20, 5), (1, 21, 4)])
def test_a_block_id_places_its_default_state_with_the_written_properties_over_it(version):
    # BlockStateParser.parse: the block's defaultBlockState, then each written property set on it
    stairs = with_defaults(parse_block("oak_stairs[half=top]"), version)
    assert dict(stairs.properties) == {"facing": "north", "half": "top", "shape": "straight", "waterlogged": "false"}
    assert dict(with_defaults(parse_block("lever"), version).properties) == {
        "face": "wall", "facing": "north", "powered": "false"}
    assert with_defaults(parse_block("stone"), version).properties == ()
    unknown = parse_block("minecraft:no_such_block[a=b]")
    assert with_defaults(unknown, version) == unknown  # not in the registries: as written
    assert with_defaults(parse_block("#minecraft:stairs"), version).properties == ()


def test_the_default_state_follows_the_release():
    # leaves took a waterlogged property in 1.19 (LeavesBlock.WATERLOGGED)
    assert "waterlogged" not in dict(with_defaults(parse_block("oak_leaves"), (1, 18, 2)).properties)
    assert dict(with_defaults(parse_block("oak_leaves"), (1, 19, 4)).properties) == {
        "distance": "7", "persistent": "false", "waterlogged": "false"}


def test_setblock_and_if_block_see_the_default_state(tmp_path):
    # SetBlockCommand places BlockInput's state (the default one for a bare id): `if block` with a
    # default property holds, and placing the same state again changes nothing ("Could not set")
    emu = emulator(tmp_path, "python", {
        "t:place": "setblock 0 1 0 minecraft:oak_stairs\n"
                   "execute store success score #north o if block 0 1 0 oak_stairs[facing=north,half=bottom]\n"
                   "execute store success score #again o run setblock 0 1 0 oak_stairs[shape=straight]\n"
                   "fill 1 1 0 2 1 0 minecraft:lever\n"
                   "execute store success score #lever o if block 2 1 0 lever[face=wall,powered=false]",
    })
    emu.call("t:place")
    assert [emu.score(h, "o") for h in ("#north", "#again", "#lever")] == [1, 0, 1]
    assert str(emu.state.blocks.get((0, 1, 0))) == (
        "minecraft:oak_stairs[facing=north,half=bottom,shape=straight,waterlogged=false]")


def test_campfires_and_suspicious_blocks_have_their_block_entities(tmp_path):
    # CampfireBlockEntity.saveAdditional: Items (always), CookingTimes and CookingTotalTimes of its
    # four slots; it is no Container, so item commands refuse it (ItemCommands.getContainer);
    # BrushableBlockEntity saves its item only when it has one
    from emulator import Emulator
    from tests.world.world_emulator import make_pack
    emu = Emulator(backend="python")
    emu.load(make_pack(tmp_path / "p", {
        "t:go": "scoreboard objectives add o dummy\nsetblock 0 0 0 campfire\nsetblock 1 0 0 suspicious_sand\n"
                "execute store success score #item o run item replace block 0 0 0 container.0 with stone\n"
                "execute store success score #data o run data get block 1 0 0"}))
    emu.call("t:go")
    fire = emu.state.blocks.entity((0, 0, 0))
    assert list(fire["Items"]) == [] and [int(v) for v in fire["CookingTimes"]] == [0, 0, 0, 0]
    assert [int(v) for v in fire["CookingTotalTimes"]] == [0, 0, 0, 0]
    assert emu.state.blocks.entity((1, 0, 0)) == {}
    assert (emu.score("#item", "o"), emu.score("#data", "o")) == (0, 1)


def _placed(block: str, version) -> BlockMap:
    world = BlockMap(lambda: version)
    world.place((0, 0, 0), with_defaults(parse_block(block), version))
    return world


@pytest.mark.parametrize("block,version,saved", [
    # BaseSpawner.save: the delays and counts as shorts, SpawnPotentials; SpawnData only once drawn
    # from 1.19.3 (nextSpawnData null), a pig before (new SpawnData())
    ("spawner", (1, 21, 0), "{Delay:20s,MinSpawnDelay:200s,MaxSpawnDelay:800s,SpawnCount:4s,MaxNearbyEntities:6s,"
                            "RequiredPlayerRange:16s,SpawnRange:4s,SpawnPotentials:[]}"),
    ("spawner", (1, 19, 2), "{SpawnData:{entity:{id:\"minecraft:pig\"}},SpawnPotentials:[]}"),
    # AbstractFurnaceBlockEntity.saveAdditional: renamed in 1.21.4 (BlockEntityFurnaceBurnTimeFix)
    ("smoker", (1, 21, 0), "{BurnTime:0s,CookTime:0s,CookTimeTotal:0s,Items:[],RecipesUsed:{}}"),
    ("furnace", (1, 21, 4), "{cooking_time_spent:0s,cooking_total_time:0s,lit_time_remaining:0s,lit_total_time:0s,"
                            "Items:[],RecipesUsed:{}}"),
    ("brewing_stand", (1, 21, 0), "{BrewTime:0s,Fuel:0b,Items:[]}"),  # BrewingStandBlockEntity.saveAdditional
    ("bee_nest", (1, 21, 0), "{bees:[]}"), ("beehive", (1, 20, 4), "{Bees:[]}"),  # BeehiveBlockEntity, 1.20.5 renames
    ("beacon", (1, 21, 0), "{Levels:0}"),  # BeaconBlockEntity: storeEffect writes no effect while none is chosen
    ("beacon", (1, 20, 1), "{Primary:-1,Secondary:-1,Levels:0}"),  # MobEffect.getIdFromNullable(null): -1
    ("hopper", (1, 21, 0), "{Items:[],TransferCooldown:-1}"),  # HopperBlockEntity: cooldownTime = -1
    ("chiseled_bookshelf", (1, 21, 0), "{Items:[],last_interacted_slot:-1}"),
    ("comparator", (1, 21, 0), "{OutputSignal:0}"), ("end_gateway", (1, 21, 0), "{Age:0L}"),
])
def test_a_new_block_entity_saves_what_the_game_saves(block, version, saved):
    world = _placed(block, version)
    wanted = snbt_or_tag(saved)
    found = world.entity((0, 0, 0))
    assert nbt_ops.tags_equal(wanted, found) if "SpawnData" not in saved else nbt_ops.compare_nbt(wanted, found)


def test_block_entity_ids_and_blocks_without_one():
    # BlockEntity.saveWithFullMetadata adds the type's id (BlockEntityType: "sign" for every sign,
    # "mob_spawner", "beehive" for a bee nest ...); an empty shulker box saves no Items
    # (ContainerHelper.saveAllItems(..., false)); BlockInput.place ignores NBT for a block without one
    version = (1, 21, 0)
    assert _placed("oak_wall_sign", version).block_nbt((0, 0, 0))["id"] == "minecraft:sign"
    assert _placed("spawner", version).block_nbt((0, 0, 0))["id"] == "minecraft:mob_spawner"
    assert _placed("bee_nest", version).block_nbt((0, 0, 0))["id"] == "minecraft:beehive"
    box = _placed("red_shulker_box", version)
    assert box.entity((0, 0, 0)) == {} and box.block_nbt((0, 0, 0))["id"] == "minecraft:shulker_box"
    for block in ("ender_chest", "enchanting_table", "red_bed", "bell", "conduit", "daylight_detector"):
        assert _placed(block, version).entity((0, 0, 0)) == {}, block
    stone = _placed("stone{Items:[]}", version)
    assert stone.entity((0, 0, 0)) is None
    with pytest.raises(CommandFailure, match="not a block entity"):
        stone.block_nbt((0, 0, 0))


def test_a_block_entity_whose_save_is_not_known_is_not_modelled():
    # a sculk sensor's vibration listener, a trial spawner, a jukebox of 1.20 (its TickCount counts
    # every tick): reading them says so instead of a wrong answer
    for block, version in (("sculk_sensor", (1, 21, 0)), ("trial_spawner", (1, 21, 0)), ("jukebox", (1, 20, 1)),
                           ("spawner", (1, 17, 1))):
        world = _placed(block, version)
        with pytest.raises(Unmodelled, match="block entity of minecraft:"):
            world.block_nbt((0, 0, 0))

@pytest.mark.parametrize("backend", ["numba", "python"])
def test_clone_counts_copies_block_entities_and_refuses_overlap(tmp_path, backend):
    """CloneCommands.clone: every block the mask takes is set to a barrier then to its state, so the
    result counts them all but barriers; a block entity goes with its block (saveCustomOnly,
    loadCustomOnly); ``filtered`` onto itself with ``force`` counts the matching blocks (a machine
    library counting its heads); ``normal`` refuses an overlap, ``move`` leaves air behind."""
    emu = emulator(tmp_path, backend, {
        "t:go": "setblock 0 0 0 chest{Items:[{Slot:0b,id:\"minecraft:stone\",count:3}]}\n"
                "setblock 1 0 0 stone\nsetblock 2 0 0 barrier\n"
                "setblock 0 0 1 player_head{components:{\"minecraft:custom_data\":{m:1b}}}\n"
                "setblock 1 0 1 player_head\n"
                "execute store result score #all o run clone 0 0 0 2 0 0 0 5 0\n"
                "execute store result score #heads o run clone 0 0 1 2 0 1 0 0 1 filtered "
                "player_head{components:{\"minecraft:custom_data\":{m:1b}}} force\n"
                "execute store success score #overlap o run clone 0 0 0 2 0 0 1 0 0\n"
                "execute store result score #masked o run clone 0 0 1 2 0 1 0 9 1 masked move\n"})
    emu.call("t:go")
    assert [emu.score(h, "o") for h in ("#all", "#heads", "#overlap", "#masked")] == [2, 1, 0, 2]
    blocks = emu.state.blocks
    assert [blocks.get((x, 5, 0)).id for x in range(3)] == ["minecraft:chest", "minecraft:stone", "minecraft:barrier"]
    assert blocks.entity((0, 5, 0))["Items"][0]["count"] == 3
    assert [blocks.get((x, 0, 1)).id for x in range(3)] == ["minecraft:air"] * 3  # moved away
    assert blocks.get((2, 9, 1)).id == "minecraft:air" and blocks.entity((0, 9, 1))["components"] == {
        "minecraft:custom_data": {"m": 1}}


def test_clone_fails_on_nothing_too_much_and_an_unknown_level(tmp_path):
    """ERROR_FAILED when no block was set (a masked box of air), ERROR_AREA_TOO_LARGE over the
    commandModificationBlockLimit, DimensionArgument's unknown dimension; ``to`` another level."""
    emu = emulator(tmp_path, "python", {
        "t:go": "setblock 0 0 0 stone\n"
                "execute store success score #air o run clone 5 5 5 6 6 6 9 9 9 masked\n"
                "execute store success score #big o run clone 0 0 0 40 40 40 100 0 0\n"
                "execute store success score #nowhere o run clone 0 0 0 0 0 0 to t:nowhere 0 0 0\n"
                "execute store result score #nether o run clone 0 0 0 0 0 0 to the_nether 0 64 0\n"})
    emu.call("t:go")
    assert [emu.score(h, "o") for h in ("#air", "#big", "#nowhere", "#nether")] == [0, 0, 0, 1]
    assert emu.state.blocks_in("minecraft:the_nether").get((0, 64, 0)).id == "minecraft:stone"
    world, barrier = BlockMap(), parse_block("barrier")
    with pytest.raises(CommandFailure, match="maximum 32768, specified 68921"):
        world.clone_to((0, 0, 0), (40, 40, 40), world, (100, 0, 0), lambda pos: True, barrier)
    with pytest.raises(CommandFailure, match="cannot overlap"):
        world.clone_to((0, 0, 0), (2, 0, 0), world, (2, 0, 0), lambda pos: True, barrier)
    assert world.clone_to((0, 0, 0), (2, 0, 0), world, (2, 0, 0), lambda pos: True, barrier, "force")[0] == 3
