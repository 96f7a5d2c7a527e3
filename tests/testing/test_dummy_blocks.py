"""PackTest's ``dummy use block POS [DIR]`` (emulator.world.block_use): the block's interaction where
a pack observes it. Sources: misode/packtest DummyCommand.useBlock (each hand in turn through
ServerPlayerGameMode.useItemOn until one consumes the action; an unknown direction is refused);
the game's ServerPlayerGameMode.useItemOn, LeverBlock.pull, ButtonBlock, NoteBlock, DoorBlock,
FenceGateBlock, ChestBlock/BarrelBlock (the statistics), BarrelBlockEntity (open), Container.
stillValidBlockEntity, DefaultBlockInteractionTrigger, ItemUsedOnLocationTrigger."""
import json

import pytest

from tests.testing.test_dummy_hands import run

LEVER_ADVANCEMENT = {
    "demo/advancement/lever.json": json.dumps({"criteria": {"c": {
        "trigger": "minecraft:default_block_use",
        "conditions": {"location": [{"condition": "minecraft:block_state_property", "block": "minecraft:lever"}]}}}}),
    "demo/advancement/chest.json": json.dumps({"criteria": {"c": {
        "trigger": "minecraft:default_block_use",
        "conditions": {"location": [{"condition": "minecraft:block_state_property", "block": "minecraft:chest"}]}}}}),
}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_lever_flips_and_fires_default_block_use(tmp_path, backend):
    result = run(tmp_path, "# @dummy\n" + (
        "setblock ~2 ~ ~ lever[face=floor,facing=north,powered=false]\n"
        "dummy @s use block ~2 ~ ~\n"
        "assert block ~2 ~ ~ lever[powered=true]\n"
        "assert entity @s[advancements={demo:lever=true,demo:chest=false}]\n"
        "dummy @s use block ~2 ~ ~ north\n"
        "assert block ~2 ~ ~ lever[powered=false,face=floor]\n"), files=LEVER_ADVANCEMENT, backend=backend)
    assert result.status == "passed", result.report()


def test_before_1_20_5_a_block_use_fires_item_used_on_block(tmp_path):
    """1.20.4 ServerPlayerGameMode.useItemOn: BlockState.use consuming the action fires
    ITEM_USED_ON_BLOCK with the held stack (default_block_use came in 24w13a)."""
    files = {"demo/advancements/lever.json": json.dumps({"criteria": {"c": {
        "trigger": "minecraft:item_used_on_block",
        "conditions": {"location": [{"condition": "minecraft:block_state_property", "block": "minecraft:lever"}]}}}})}
    result = run(tmp_path, "# @dummy\nsetblock ~2 ~ ~ lever\ndummy @s use block ~2 ~ ~\n"
                           "assert entity @s[advancements={demo:lever=true}]\n", pack_format=26, files=files)
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("button, ticks", [("oak_button", 30), ("stone_button", 20)])
def test_a_button_springs_back_after_its_ticks(tmp_path, button, ticks):
    result = run(tmp_path, "# @dummy\n" + (
        f"setblock ~2 ~ ~ {button}[powered=false]\n"
        "dummy @s use block ~2 ~ ~\n"
        f"assert block ~2 ~ ~ {button}[powered=true]\n"
        f"await delay {ticks - 1}\n"
        f"assert block ~2 ~ ~ {button}[powered=true]\n"
        "dummy @s use block ~2 ~ ~\n"                   # pressed: the use is consumed, nothing changes
        "await delay 1\n"
        f"assert block ~2 ~ ~ {button}[powered=false]\n"))
    assert result.status == "passed", result.report()


def test_a_note_block_is_tuned_up_a_note(tmp_path):
    result = run(tmp_path, "# @dummy\n" + (
        "scoreboard objectives add tuned minecraft.custom:minecraft.tune_noteblock\n"
        "setblock ~2 ~ ~ note_block[note=23]\n"
        "dummy @s use block ~2 ~ ~\n"
        "assert block ~2 ~ ~ note_block[note=24]\n"
        "dummy @s use block ~2 ~ ~\n"
        "assert block ~2 ~ ~ note_block[note=0]\n"
        "assert score @s tuned matches 2\n"))
    assert result.status == "passed", result.report()


def test_containers_count_their_statistic_and_a_barrel_opens_while_in_reach(tmp_path):
    result = run(tmp_path, "# @dummy\n" + (
        "scoreboard objectives add chests minecraft.custom:minecraft.open_chest\n"
        "scoreboard objectives add traps custom:trigger_trapped_chest\n"
        "scoreboard objectives add barrels custom:open_barrel\n"
        "scoreboard objectives add crafting custom:interact_with_crafting_table\n"
        "setblock ~2 ~ ~ chest\nsetblock ~2 ~ ~1 trapped_chest\nsetblock ~1 ~ ~2 barrel[open=false]\n"
        "setblock ~ ~ ~2 crafting_table\n"
        "dummy @s use block ~2 ~ ~\n"
        "dummy @s use block ~2 ~ ~1\n"
        "dummy @s use block ~ ~ ~2\n"
        "assert score @s chests matches 1\nassert score @s traps matches 1\nassert score @s crafting matches 1\n"
        "dummy @s use block ~1 ~ ~2\n"
        "assert block ~1 ~ ~2 barrel[open=true]\n"
        "assert score @s barrels matches 1\n"
        "dummy @s use block ~2 ~ ~\n"                   # opening another menu closes the barrel's
        "assert block ~1 ~ ~2 barrel[open=false]\n"
        "dummy @s use block ~1 ~ ~2\n"
        "tp @s ~ ~ ~9\n"                                  # still within 4.5 + 4 of the barrel's box
        "await delay 1\n"
        "assert block ~1 ~ ~2 barrel[open=true]\n"
        "tp @s ~ ~ ~12\n"
        "await delay 1\n"
        "assert block ~1 ~ ~2 barrel[open=false]\n"), files=LEVER_ADVANCEMENT)
    assert result.status == "passed", result.report()


def test_doors_gates_and_iron(tmp_path):
    result = run(tmp_path, "# @dummy\n" + (
        "setblock ~2 ~ ~ oak_door[half=lower,open=false]\nsetblock ~2 ~1 ~ oak_door[half=upper,open=false]\n"
        "dummy @s use block ~2 ~1 ~\n"
        "assert block ~2 ~ ~ oak_door[half=lower,open=true]\nassert block ~2 ~1 ~ oak_door[half=upper,open=true]\n"
        "setblock ~ ~ ~2 oak_fence_gate[facing=south,open=false]\n"  # the dummy looks south (yaw 0)
        "dummy @s use block ~ ~ ~2\n"
        "assert block ~ ~ ~2 oak_fence_gate[facing=south,open=true]\n"
        "setblock ~ ~ ~2 oak_fence_gate[facing=north,open=false]\n"
        "dummy @s use block ~ ~ ~2\n"
        "assert block ~ ~ ~2 oak_fence_gate[facing=south,open=true]\n"
        "setblock ~2 ~ ~2 iron_trapdoor[open=false]\n"
        "dummy @s use block ~2 ~ ~2\n"
        "assert block ~2 ~ ~2 iron_trapdoor[open=false]\n"
        "fail \"end\"\n"))
    assert (result.status, result.message) == ("failed", "end"), result.report()
    assert "cannot interact with that block" in "\n".join(result.details)


def test_a_plain_block_with_empty_hands_refuses_and_an_unknown_direction_is_refused(tmp_path):
    result = run(tmp_path, "# @dummy\nsetblock ~2 ~ ~ stone\ndummy @s use block ~2 ~ ~\n"
                           "dummy @s use block ~2 ~ ~ sideways\nfail \"end\"\n")
    assert (result.status, result.message) == ("failed", "end")
    details = "\n".join(result.details)
    assert "use block ~2 ~ ~: Dummy" in details and "cannot interact with that block" in details
    assert "use block ~2 ~ ~ sideways: Not a valid direction" in details


@pytest.mark.parametrize("setup, reason", [
    ("give @s firework_rocket\nsetblock ~2 ~ ~ stone", "using minecraft:firework_rocket on minecraft:stone"),
    ("give @s firework_rocket\ndummy @s sneak true\nsetblock ~2 ~ ~ lever", "using minecraft:firework_rocket on minecraft:lever"),
    ("setblock ~2 ~ ~ chest\nsetblock ~2 ~1 ~ stone", "opening minecraft:chest under minecraft:stone"),
    ("setblock ~2 ~ ~ chest{LootTable:\"demo:x\"}", "unpacking its loot table"),
    ("setblock ~2 ~ ~ cake", "using the block minecraft:cake"),
])
def test_what_is_not_modelled_makes_the_test_inconclusive(tmp_path, setup, reason):
    result = run(tmp_path, f"# @dummy\n{setup}\ndummy @s use block ~2 ~ ~\nsucceed\n")
    assert result.status == "inconclusive", result.report()
    assert reason in result.message


DIRT_TABLE = {"minecraft/loot_table/blocks/dirt.json": json.dumps({"pools": [{"rolls": 1, "entries": [
    {"type": "minecraft:item", "name": "minecraft:diamond"}]}]})}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_survival_mining_drops_the_block_loot_and_counts_mined(tmp_path, backend):
    """ServerPlayerGameMode.destroyBlock -> Block.playerDestroy: mined:<block>, exhaustion 0.005,
    the block's loot table (here a pack's) popped about the block's centre; a block that needs a
    tool is removed without drops or statistic."""
    result = run(tmp_path, "# @dummy\n" + (
        "scoreboard objectives add dirt minecraft.mined:minecraft.dirt\n"
        "scoreboard objectives add stone minecraft.mined:minecraft.stone\n"
        "setblock ~2 ~ ~ dirt\nsetblock ~2 ~1 ~ stone\n"
        "dummy @s mine ~2 ~ ~\n"
        "assert block ~2 ~ ~ air\n"
        "assert entity @e[type=item,nbt={Item:{id:\"minecraft:diamond\"},PickupDelay:10s},x=2,y=1,z=0,dx=0.99,dy=0.99,dz=0.99]\n"
        "assert score @s dirt matches 1\n"
        "assert data entity @s {foodExhaustionLevel:0.005f}\n"
        "dummy @s mine ~2 ~1 ~\n"
        "assert block ~2 ~1 ~ air\n"
        "assert not score @s stone matches 1..\n"
        "execute store result score #items dirt if entity @e[type=item]\n"
        "assert score #items dirt matches 1\n"), files=DIRT_TABLE, backend=backend)
    assert result.status == "passed", result.report()


def test_operator_blocks_refuse_and_adventure_players_cannot_mine(tmp_path):
    result = run(tmp_path, "# @dummy\nsetblock ~2 ~ ~ command_block\ndummy @s mine ~2 ~ ~\n"
                           "assert block ~2 ~ ~ command_block\ngamemode adventure @s\nsetblock ~2 ~1 ~ dirt\n"
                           "dummy @s mine ~2 ~1 ~\nassert block ~2 ~1 ~ dirt\nfail \"end\"\n", files=DIRT_TABLE)
    assert (result.status, result.message) == ("failed", "end"), result.report()
    assert "\n".join(result.details).count("failed to mine block") == 2


@pytest.mark.parametrize("setup, reason", [
    ("setblock ~2 ~ ~ grass_block", "the game's own loot table minecraft:blocks/grass_block"),
    ("setblock ~2 ~ ~ dirt\ngive @s diamond_pickaxe[enchantments={levels:{\"demo:brittle\":1}}]",
     "the item_damage effects of demo:brittle"),
    ("setblock ~2 ~ ~ stone\ngive @s iron_pickaxe", "the vanilla block tag #minecraft:incorrect_for_iron_tool"),
    ("setblock ~2 ~ ~ magma_block", "whether it needs the right tool"),
    ("setblock ~2 ~ ~ oak_door[half=lower]", "its other half"),
])
def test_survival_mining_the_emulator_cannot_model_is_inconclusive(tmp_path, setup, reason):
    result = run(tmp_path, f"# @dummy\n{setup}\ndummy @s mine ~2 ~ ~\nsucceed\n", files=DIRT_TABLE)
    assert result.status == "inconclusive", result.report()
    assert reason in result.message


PLACED = {"demo/advancement/placed.json": json.dumps({"criteria": {"c": {
    "trigger": "minecraft:placed_block",
    "conditions": {"location": [{"condition": "minecraft:block_state_property", "block": "minecraft:stone"}]}}}}),
    "demo/advancement/used_on.json": json.dumps({"criteria": {"c": {
        "trigger": "minecraft:item_used_on_block",
        "conditions": {"location": [{"condition": "minecraft:match_tool", "predicate": {"items": "minecraft:stone"}},
                                    {"condition": "minecraft:block_state_property", "block": "minecraft:dirt"}]}}}})}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_block_item_places_its_block_beside_the_clicked_face(tmp_path, backend):
    """BlockItem.useOn -> place: BlockPlaceContext puts it on the neighbour in the face's direction
    (the clicked block is not replaceable), spends one item, counts used:<item>, fires placed_block
    (the placed block) and item_used_on_block (the clicked block, the stack as it was)."""
    result = run(tmp_path, "# @dummy\n" + (
        "scoreboard objectives add used minecraft.used:minecraft.stone\n"
        "setblock ~2 ~ ~ dirt\n"
        "give @s stone 2\n"
        "dummy @s use block ~2 ~ ~ up\n"
        "assert block ~2 ~1 ~ stone\n"
        "assert block ~2 ~ ~ dirt\n"
        "assert items entity @s weapon.mainhand stone[count=1]\n"
        "assert score @s used matches 1\n"
        "assert entity @s[advancements={demo:placed=true,demo:used_on=true}]\n"
        "dummy @s use block ~2 ~1 ~ east\n"
        "assert block ~3 ~1 ~ stone\n"
        "assert not items entity @s weapon.mainhand *\n"), files=PLACED, backend=backend)
    assert result.status == "passed", result.report()


def test_placing_replaces_grass_and_refuses_a_full_spot_or_an_entity_in_the_way(tmp_path):
    result = run(tmp_path, "# @dummy\n" + (
        "setblock ~2 ~ ~ short_grass\n"
        "give @s stone 3\n"
        "dummy @s use block ~2 ~ ~ up\n"
        "assert block ~2 ~ ~ stone\n"                     # the grass is replaced, not built upon
        "setblock ~2 ~1 ~ dirt\n"
        "dummy @s use block ~2 ~ ~ up\n"                  # the spot above is taken
        "summon pig ~ ~ ~2\n"
        "setblock ~ ~-1 ~2 dirt\n"
        "dummy @s use block ~ ~-1 ~2 up\n"                # the pig stands there
        "assert block ~ ~ ~2 air\n"
        "assert items entity @s weapon.mainhand stone[count=2]\n"
        "fail \"end\"\n"))
    assert (result.status, result.message) == ("failed", "end"), result.report()
    assert "\n".join(result.details).count("cannot interact with that block") == 2


@pytest.mark.parametrize("item, reason", [
    ("oak_fence", "placing minecraft:oak_fence (its state follows how it is placed"),
    ("pig_spawn_egg", "using minecraft:pig_spawn_egg on minecraft:dirt"),
])
def test_placements_the_emulator_cannot_model_are_inconclusive(tmp_path, item, reason):
    result = run(tmp_path, f"# @dummy\nsetblock ~2 ~ ~ dirt\ngive @s {item}\ndummy @s use block ~2 ~ ~ up\nsucceed\n")
    assert result.status == "inconclusive", result.report()
    assert reason in result.message


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_lectern_takes_a_book_then_opens_its_menu(tmp_path, backend):
    """LecternBlock.useItemOn (a lectern book placed: tryPlaceBook -> placeBook, resetBookState; the
    criterion item_used_on_block), useWithoutItem (with a book: openScreen, interact_with_lectern;
    without: consumed all the same, default_block_use), LecternBlockEntity.saveAdditional (Book, Page)."""
    files = {"demo/advancement/book.json": json.dumps({"criteria": {"c": {
        "trigger": "minecraft:item_used_on_block", "conditions": {"location": [
            {"condition": "minecraft:match_tool", "predicate": {"items": "minecraft:writable_book"}}]}}}}),
        "demo/advancement/empty.json": json.dumps({"criteria": {"c": {"trigger": "minecraft:default_block_use"}}})}
    result = run(tmp_path, "# @dummy\n" + (
        "scoreboard objectives add lecterns minecraft.custom:minecraft.interact_with_lectern\n"
        "setblock ~2 ~ ~ lectern\n"
        "assert data block ~2 ~ ~ {}\n"
        "give @s stone\n"
        "dummy @s use block ~2 ~ ~\n"                     # no book: the use is consumed
        "assert entity @s[advancements={demo:empty=true,demo:book=false}]\n"
        "assert block ~2 ~ ~ lectern[has_book=false]\n"
        "clear @s stone\n"
        "give @s writable_book\n"
        "dummy @s use block ~2 ~ ~\n"
        "assert block ~2 ~ ~ lectern[has_book=true,powered=false]\n"
        "assert data block ~2 ~ ~ {Book:{id:\"minecraft:writable_book\",count:1},Page:0}\n"
        "assert not items entity @s weapon.mainhand *\n"
        "assert entity @s[advancements={demo:book=true}]\n"
        "assert not score @s lecterns matches 1..\n"
        "dummy @s use block ~2 ~ ~\n"                     # a book on it: its menu opens
        "assert score @s lecterns matches 1\n"), files=files, backend=backend)
    assert result.status == "passed", result.report()
