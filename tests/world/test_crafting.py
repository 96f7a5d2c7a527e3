"""Crafting recipes matched as the game matches them (emulator.world.crafting), and a crafter's
refusals. Sources (decompiled 1.21): CraftingInput.ofPositioned, ShapedRecipePattern (shrink,
matches with its mirror), ShapelessRecipe.matches (StackedContents.canCraft), Ingredient.test,
CraftingRecipe.getRemainingItems, CrafterBlock.dispenseItem / HopperBlockEntity.getContainerAt."""
from __future__ import annotations

import json

import pytest

from emulator.world import crafting, items
from emulator.world.errors import Unmodelled
from emulator.world.items import EMPTY, ItemStack
from emulator.world.resources import Resources
from emulator import Emulator
from mcfunction_parser.nbt import Compound, Int, List, String
from mcfunction_parser.pack.registry_tags import RegistryTag
from tests.world.world_emulator import make_pack

V121 = (1, 21, 0)
TORCH = {"type": "minecraft:crafting_shaped", "pattern": ["   ", " C ", " S "],
         "key": {"C": {"item": "minecraft:coal"}, "S": {"item": "minecraft:stick"}},
         "result": {"id": "minecraft:torch", "count": 4}}
L_SHAPE = {"type": "minecraft:crafting_shaped", "pattern": ["A ", "AB"],
           "key": {"A": {"item": "minecraft:stone"}, "B": {"item": "minecraft:dirt"}},
           "result": {"id": "minecraft:cobblestone"}}
MIX = {"type": "minecraft:crafting_shapeless",
       "ingredients": [[{"item": "minecraft:stone"}, {"item": "minecraft:dirt"}], {"item": "minecraft:stone"}],
       "result": {"id": "minecraft:gravel", "count": 2}}


def _resources(**recipes):
    return Resources(recipes={k: v["type"] for k, v in recipes.items()}, recipe_bodies=dict(recipes))


def _grid(cells: dict[int, str]) -> list[ItemStack]:
    return [ItemStack("minecraft:" + cells[i]) if i in cells else EMPTY.copy() for i in range(9)]


def test_a_shaped_pattern_is_trimmed_and_matches_anywhere_in_the_grid():
    res = _resources(**{"t:torch": TORCH})
    for top in (0, 3):  # coal above stick, in any column of the grid
        for column in range(3):
            found = crafting.craft(res, _grid({top + column: "coal", top + 3 + column: "stick"}), V121)
            assert (found.recipe_id, found.result.id, found.result.count) == ("t:torch", "minecraft:torch", 4)
    # an extra stack, or the shape upside down, is no torch
    assert _no_vanilla(res, _grid({0: "coal", 3: "stick", 8: "stick"})) is None
    assert _no_vanilla(res, _grid({0: "stick", 3: "coal"})) is None


def _no_vanilla(res, grid):
    """craft() with the game's data said to be loaded (none of its recipes here): no match is None."""
    res.vanilla_data = True
    try:
        return crafting.craft(res, grid, V121)
    finally:
        res.vanilla_data = False


def test_the_mirror_of_an_asymmetric_pattern_matches():
    res = _resources(**{"t:l": L_SHAPE})
    assert crafting.craft(res, _grid({0: "stone", 3: "stone", 4: "dirt"}), V121).recipe_id == "t:l"
    assert crafting.craft(res, _grid({1: "stone", 4: "stone", 3: "dirt"}), V121).recipe_id == "t:l"  # mirrored
    assert _no_vanilla(res, _grid({0: "stone", 3: "dirt", 4: "stone"})) is None


def test_shapeless_uses_each_stack_once_whatever_the_order():
    res = _resources(**{"t:mix": MIX})
    # dirt first: a greedy pairing of stone with the either-ingredient would fail; canCraft does not
    for cells in ({0: "dirt", 8: "stone"}, {4: "stone", 5: "stone"}, {2: "stone", 6: "dirt"}):
        assert crafting.craft(res, _grid(cells), V121).result.count == 2
    assert _no_vanilla(res, _grid({0: "dirt", 1: "dirt"})) is None
    assert _no_vanilla(res, _grid({0: "stone", 1: "stone", 2: "stone"})) is None


def test_ingredients_test_the_item_only_and_buckets_leave_a_bucket():
    recipe = {"type": "minecraft:crafting_shapeless", "ingredients": ["minecraft:milk_bucket", "#t:sweet"],
              "result": {"id": "minecraft:cake", "components": {"minecraft:custom_data": {"k": 1}}}}
    res = _resources(**{"t:cake": recipe})
    from mcfunction_parser.pack.registry_tags import RegistryTag
    res.tags = {"item": {"t:sweet": RegistryTag(frozenset({"minecraft:sugar"}))}}
    grid = _grid({0: "milk_bucket", 4: "sugar"})
    grid[4].patch["minecraft:custom_data"] = {"whatever": 1}  # components are not tested
    found = crafting.craft(res, grid, (1, 21, 4))
    assert found.result.patch == {"minecraft:custom_data": {"k": 1}}
    assert [s.id for s in found.remainders] == ["minecraft:bucket", "minecraft:air", "minecraft:air",
                                                "minecraft:air", "minecraft:air"][:len(found.remainders)]


def test_without_the_games_recipes_a_grid_no_pack_recipe_makes_is_not_modelled():
    res = _resources(**{"t:torch": TORCH})
    with pytest.raises(Unmodelled, match="--game-jar"):
        crafting.craft(res, _grid({0: "oak_log"}), V121)
    # a special recipe loaded (from the jar) that might match is said so
    res = _resources(**{"minecraft:firework_star": {"type": "minecraft:crafting_special_firework_star"}})
    res.vanilla_data = True
    with pytest.raises(Unmodelled, match="crafting_special_firework_star"):
        crafting.craft(res, _grid({0: "gunpowder", 1: "red_dye"}), V121)
    assert crafting.craft(res, _grid({}), V121) is None  # an empty grid crafts nothing


def _crafter_pack(tmp_path, setup: str):
    pack = make_pack(tmp_path / "p", {"t:main": setup + "\nitem replace block 0 0 0 container.0 with dirt\n"
                                      "setblock 0 1 0 redstone_block"})
    (pack / "data/t/recipe").mkdir(parents=True)
    (pack / "data/t/recipe/d.json").write_text(json.dumps({"type": "crafting_shapeless", "ingredients": [
        {"item": "dirt"}], "result": {"id": "minecraft:coarse_dirt"}}))
    return pack


@pytest.mark.parametrize("backend", ["python", "numba"])
def test_a_crafter_fills_a_furnace_through_the_face_it_meets(tmp_path, backend):
    # CrafterBlock.dispenseItem: HopperBlockEntity.addItem(..., direction.getOpposite()): a crafter facing
    # down meets the furnace's top, whose slot is the input (AbstractFurnaceBlockEntity.getSlotsForFace)
    emu = Emulator(backend=backend)
    emu.load(_crafter_pack(tmp_path, "setblock 0 0 0 crafter[orientation=down_north]\nsetblock 0 -1 0 furnace"))
    emu.call("t:main")
    emu.tick(5)
    items = emu.state.blocks.entity((0, -1, 0))["Items"]
    assert [(int(i["Slot"]), str(i["id"])) for i in items] == [(0, "minecraft:coarse_dirt")]
    assert not any(d.unmodelled for d in emu.diagnostics)


def test_a_crafter_facing_a_decorated_pot_is_not_modelled(tmp_path):
    # a decorated pot as a container is not modelled: the craft stops there, said so
    emu = Emulator(backend="python")
    emu.load(_crafter_pack(tmp_path, "setblock 0 0 0 crafter[orientation=east_up]\nsetblock 1 0 0 decorated_pot"))
    emu.call("t:main")
    assert not any(d.unmodelled for d in emu.diagnostics)
    emu.tick(5)
    assert any(d.unmodelled and "into minecraft:decorated_pot" in d.message for d in emu.diagnostics)


def test_the_recipes_are_tried_in_the_games_order():
    # RecipeManager.prepare (1.21.2+): a TreeMap by id, ResourceLocation.compareTo (path, then
    # namespace); before, a HashMap's order (pinned against java.util.HashMap on OpenJDK 17 with
    # ResourceLocation's hashCode, 31 * namespace.hashCode() + path.hashCode())
    ids = ["minecraft:torch", "t:a", "t:b", "minecraft:stick", "a:x/y", "b:a-b", "ns:zz", "minecraft:oak_planks"]
    assert crafting.recipe_order(ids, (1, 21, 2)) == [
        "t:a", "b:a-b", "t:b", "minecraft:oak_planks", "minecraft:stick", "minecraft:torch", "a:x/y", "ns:zz"]
    assert crafting.recipe_order(ids, V121) == [
        "a:x/y", "b:a-b", "minecraft:torch", "minecraft:oak_planks", "ns:zz", "t:a", "t:b", "minecraft:stick"]
    two = {"type": "minecraft:crafting_shapeless", "ingredients": ["minecraft:stone"], "result": {"id": "minecraft:dirt"}}
    res = _resources(**{"t:b": two, "t:a": {**two, "result": {"id": "minecraft:gravel"}}})
    assert crafting.craft(res, _grid({0: "stone"}), (1, 21, 4)).result.id == "minecraft:gravel"  # t:a first
    # before 1.21.2 the order hangs on the table's size, so on the game's own recipes
    with pytest.raises(Unmodelled, match="both match"):
        crafting.craft(res, _grid({0: "stone"}), V121)
    res.vanilla_data = True
    assert crafting.craft(res, _grid({0: "stone"}), V121).recipe_id == "t:a"


def test_a_transmute_recipe_keeps_the_inputs_components():
    # TransmuteRecipe (1.21.2 - 1.21.4): exactly the input (not already the result) and one material;
    # assemble: transmuteCopy(result, 1), the input's component patch on the result item
    recipe = {"type": "minecraft:crafting_transmute", "input": "#t:swords", "material": "minecraft:diamond",
              "result": "minecraft:diamond_sword"}
    res = _resources(**{"t:upgrade": recipe})
    res.tags = {"item": {"t:swords": RegistryTag(frozenset({"minecraft:stone_sword", "minecraft:diamond_sword"}))}}
    sword = ItemStack("minecraft:stone_sword")
    items.set_component(sword, "minecraft:damage", Int(7))
    items.set_component(sword, "minecraft:custom_name", String("Old"))
    grid = [sword, EMPTY.copy(), EMPTY.copy(), EMPTY.copy(), ItemStack("minecraft:diamond")] + [EMPTY.copy()] * 4
    made = crafting.craft(res, grid, (1, 21, 4)).result
    assert (made.id, made.count) == ("minecraft:diamond_sword", 1)
    assert made.component("minecraft:damage") == Int(7) and made.component("minecraft:custom_name") == String("Old")
    res.vanilla_data = True  # none of the game's recipes here: no match is no craft
    for cells in ({0: "diamond_sword", 4: "diamond"}, {0: "stone_sword", 4: "diamond", 8: "diamond"}, {0: "stone_sword"}):
        assert crafting.craft(res, _grid(cells), (1, 21, 4)) is None


def test_a_transmute_recipe_from_1_21_5_applies_its_result():
    # TransmuteResult (1.21.5+; 1.21.11's source): the result an id or {id, count, components};
    # apply = transmuteCopy(item, count) then the result's component patch; TransmuteRecipe.matches
    # refuses an input the result leaves unchanged (isResultUnchanged: one item, same components)
    recipe = {"type": "minecraft:crafting_transmute", "input": "#t:boxes", "material": "minecraft:blue_dye",
              "result": {"id": "minecraft:blue_shulker_box", "count": 2,
                         "components": {"minecraft:rarity": "epic", "!minecraft:custom_name": {}}}}
    res = _resources(**{"t:dye": recipe})
    res.tags = {"item": {"t:boxes": RegistryTag(frozenset({"minecraft:shulker_box", "minecraft:blue_shulker_box"}))}}
    res.vanilla_data = True
    box = ItemStack("minecraft:shulker_box")
    items.set_component(box, "minecraft:custom_name", String("Loot"))
    items.set_component(box, "minecraft:lore", List([String("kept")]))
    made = crafting.craft(res, [box, ItemStack("minecraft:blue_dye")] + [EMPTY.copy()] * 7, (1, 21, 5)).result
    assert (made.id, made.count) == ("minecraft:blue_shulker_box", 2)
    assert made.component("minecraft:lore") == List([String("kept")]) and made.component("minecraft:custom_name") is None
    assert made.component("minecraft:rarity") == String("epic")
    # an input already what the result makes of it: the recipe does not match (no craft)
    recipe["result"] = "minecraft:blue_shulker_box"
    assert crafting.craft(res, _grid({0: "blue_shulker_box", 1: "blue_dye"}), (1, 21, 5)) is None
    assert crafting.craft(res, _grid({0: "shulker_box", 1: "blue_dye"}), (1, 21, 11)).result.id == "minecraft:blue_shulker_box"


def test_a_special_recipe_is_not_modelled_only_where_it_could_match():
    # a crafting_special_* recipe can only match a grid holding what it needs (BookCloningRecipe a
    # written book, FireworkStarRecipe gunpowder ...): elsewhere the next recipe in order is the craft
    res = _resources(**{"minecraft:firework_star": {"type": "minecraft:crafting_special_firework_star"},
                        "t:torch": TORCH})
    res.vanilla_data = True
    assert crafting.craft(res, _grid({1: "coal", 4: "stick"}), V121).recipe_id == "t:torch"
    with pytest.raises(Unmodelled, match="firework_star"):
        crafting.craft(res, _grid({0: "gunpowder", 1: "red_dye"}), V121)


def test_a_crafters_disabled_slots_and_triggered_state_are_saved_as_the_game_saves_them(tmp_path):
    # CrafterBlock.newBlockEntity: triggered as the placed state; CrafterBlockEntity.loadAdditional:
    # disabled_slots keeps the slots 0 - 8 that hold no item (slotCanBeDisabled), saveAdditional
    # writes them in slot order; setItem enables a disabled slot it fills
    emu = Emulator(backend="python")
    emu.load(make_pack(tmp_path / "p", {"t:go": "\n".join([
        "setblock 5 0 0 crafter[triggered=true]",
        "setblock 0 0 0 crafter{disabled_slots:[I;8,0,4,9,4],Items:[{Slot:4b,id:'minecraft:stone',count:1}]}",
        "item replace block 0 0 0 container.0 with minecraft:dirt"])}))
    emu.call("t:go")
    placed, loaded = emu.state.blocks.entity((5, 0, 0)), emu.state.blocks.entity((0, 0, 0))
    assert placed["triggered"] == Int(1) and list(placed["disabled_slots"]) == []
    assert [int(v) for v in loaded["disabled_slots"]] == [8] and loaded["triggered"] == Int(0)


def test_book_and_map_cloning_copy_the_original():
    # BookCloningRecipe (1.21): one written book and writable books; the copies a generation later
    # (WrittenBookContent.tryCraftCopy: none past a copy of a copy), the original left as a
    # remainder; MapCloningRecipe: one filled map and empty maps make the map, one more of it
    res = _resources(**{"minecraft:book_cloning": {"type": "minecraft:crafting_special_bookcloning"},
                        "minecraft:map_cloning": {"type": "minecraft:crafting_special_mapcloning"}})
    res.vanilla_data = True
    book = ItemStack("minecraft:written_book")
    items.set_component(book, "minecraft:written_book_content", Compound(
        title=Compound(raw=String("T")), author=String("A"), pages=List()))
    grid = [book, ItemStack("minecraft:writable_book"), EMPTY.copy(), ItemStack("minecraft:writable_book")] + [EMPTY.copy()] * 5
    made = crafting.craft(res, grid, V121)
    assert made.recipe_id == "minecraft:book_cloning" and made.result.count == 2
    assert made.result.component("minecraft:written_book_content")["generation"] == Int(1)
    assert made.remainders[0].id == "minecraft:written_book" and made.remainders[0].count == 1
    copy_of_copy = made.result.copy()
    copy_of_copy.component("minecraft:written_book_content")["generation"] = Int(2)
    assert crafting.craft(res, [copy_of_copy, ItemStack("minecraft:writable_book")] + [EMPTY.copy()] * 7,
                          V121).result.is_empty
    assert crafting.craft(res, _grid({0: "written_book", 1: "writable_book", 2: "paper"}), V121) is None
    filled = ItemStack("minecraft:filled_map")
    items.set_component(filled, "minecraft:map_id", Int(3))
    maps = crafting.craft(res, [filled] + [ItemStack("minecraft:map")] * 2 + [EMPTY.copy()] * 6, V121).result
    assert (maps.id, maps.count, maps.component("minecraft:map_id")) == ("minecraft:filled_map", 3, Int(3))
    # 26.1 made them data-driven: not modelled there
    with pytest.raises(Unmodelled, match="map_cloning"):
        crafting.craft(res, [filled, ItemStack("minecraft:map")] + [EMPTY.copy()] * 7, (26, 1, 0))


def test_firework_rockets_and_tipped_arrows_are_crafted():
    # FireworkRocketRecipe (1.21): one paper, 1 - 3 gunpowder, firework stars; three rockets with
    # Fireworks(gunpowder, the stars' explosions); TippedArrowRecipe: eight arrows round a lingering
    # potion in a full 3 x 3 grid make eight tipped arrows with its potion contents
    res = _resources(**{"minecraft:firework_rocket": {"type": "minecraft:crafting_special_firework_rocket"},
                        "minecraft:tipped_arrow": {"type": "minecraft:crafting_special_tippedarrow"}})
    res.vanilla_data = True
    star = ItemStack("minecraft:firework_star")
    items.set_component(star, "minecraft:firework_explosion", Compound(shape=String("star")))
    grid = [ItemStack("minecraft:paper"), ItemStack("minecraft:gunpowder"), ItemStack("minecraft:gunpowder"), star] + [EMPTY.copy()] * 5
    made = crafting.craft(res, grid, V121).result
    assert (made.id, made.count) == ("minecraft:firework_rocket", 3)
    assert made.component("minecraft:fireworks") == Compound(flight_duration=2, explosions=List([Compound(shape=String("star"))]))
    plain = crafting.craft(res, _grid({0: "paper", 1: "gunpowder"}), V121).result
    assert "minecraft:fireworks" not in plain.patch  # Fireworks(1, []) is the rocket's default
    assert crafting.craft(res, _grid({0: "paper"}), V121) is None
    assert crafting.craft(res, _grid({0: "paper", 1: "gunpowder", 2: "gunpowder", 3: "gunpowder", 4: "gunpowder"}), V121) is None
    potion = ItemStack("minecraft:lingering_potion")
    items.set_component(potion, "minecraft:potion_contents", Compound(potion=String("minecraft:swiftness")))
    grid = [ItemStack("minecraft:arrow")] * 4 + [potion] + [ItemStack("minecraft:arrow")] * 4
    made = crafting.craft(res, grid, V121).result
    assert (made.id, made.count) == ("minecraft:tipped_arrow", 8)
    assert made.component("minecraft:potion_contents") == Compound(potion=String("minecraft:swiftness"))
    assert crafting.craft(res, grid[:8] + [EMPTY.copy()], V121) is None


def test_a_shulker_box_is_dyed_keeping_its_contents():
    # ShulkerBoxColoring (1.20.5 - 1.21.1): one shulker box and one dye make the box of that colour,
    # transmuteCopy keeping its components; 1.21.2 replaced it with transmute recipes
    res = _resources(**{"minecraft:shulker_box_coloring": {"type": "minecraft:crafting_special_shulkerboxcoloring"}})
    res.vanilla_data = True
    box = ItemStack("minecraft:red_shulker_box")
    items.set_component(box, "minecraft:custom_name", String("Loot"))
    made = crafting.craft(res, [EMPTY.copy(), box, ItemStack("minecraft:lime_dye")] + [EMPTY.copy()] * 6, V121).result
    assert (made.id, made.count) == ("minecraft:lime_shulker_box", 1) and made.component("minecraft:custom_name") == String("Loot")
    assert crafting.craft(res, _grid({0: "shulker_box", 1: "lime_dye", 2: "red_dye"}), V121) is None
    assert crafting.craft(res, _grid({0: "shulker_box", 1: "stick"}), V121) is None
