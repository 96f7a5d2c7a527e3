"""Crafting recipes matched as the game matches them (emulator.world.crafting), and a crafter's
refusals. Sources (decompiled 1.21): CraftingInput.ofPositioned, ShapedRecipePattern (shrink,
matches with its mirror), ShapelessRecipe.matches (StackedContents.canCraft), Ingredient.test,
CraftingRecipe.getRemainingItems, CrafterBlock.dispenseItem / HopperBlockEntity.getContainerAt."""
from __future__ import annotations

import json

import pytest

from emulator.world import crafting
from emulator.world.errors import Unmodelled
from emulator.world.items import EMPTY, ItemStack
from emulator.world.resources import Resources
from emulator import Emulator
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
    res = _resources(**{"minecraft:firework_rocket": {"type": "minecraft:crafting_special_firework_rocket"}})
    res.vanilla_data = True
    with pytest.raises(Unmodelled, match="crafting_special_firework_rocket"):
        crafting.craft(res, _grid({0: "paper", 1: "gunpowder"}), V121)
    assert crafting.craft(res, _grid({}), V121) is None  # an empty grid crafts nothing


@pytest.mark.parametrize("backend", ["python", "numba"])
def test_a_crafter_facing_a_furnace_is_not_modelled(tmp_path, backend):
    # a furnace takes items by face and slot rules (WorldlyContainer) the emulator does not model;
    # the craft stops there, said so
    pack = make_pack(tmp_path / "p", {"t:main": "setblock 0 0 0 crafter[orientation=east_up]\nsetblock 1 0 0 furnace\n"
                                      "item replace block 0 0 0 container.0 with dirt\nsetblock 0 1 0 redstone_block"})
    (pack / "data/t/recipe").mkdir(parents=True)
    (pack / "data/t/recipe/d.json").write_text(json.dumps({"type": "crafting_shapeless", "ingredients": [
        {"item": "dirt"}], "result": {"id": "minecraft:coarse_dirt"}}))
    emu = Emulator(backend=backend)
    emu.load(pack)
    emu.call("t:main")
    assert not any(d.unmodelled for d in emu.diagnostics)
    emu.tick(5)
    assert any(d.unmodelled and "into minecraft:furnace" in d.message for d in emu.diagnostics)
