"""Recipes as the loader reads them: checked as the game decodes them (RecipeManager skips a recipe
that does not parse), each problem at its line and column, the rest of the pack loaded. Sources:
decompiled 1.21 ShapedRecipePattern (Data.MAP_CODEC, unpack), ShapelessRecipe.Serializer,
Ingredient.CODEC_NONEMPTY, ItemStack.STRICT_CODEC, RecipeSerializer; 1.21.2's ingredient form
(an id, a '#tag' or a list of ids) from the minecraft.wiki "Recipe" page."""
from __future__ import annotations

import json

from mcfunction_parser import load_packs
from tests.conftest import write_pack

SMELT = {"type": "smelting", "ingredient": {"item": "minecraft:cobblestone"}, "result": {"id": "minecraft:stone"}}
SHAPED = {"type": "minecraft:crafting_shaped", "pattern": ["##", "##"], "key": {"#": {"item": "minecraft:stick"}},
          "result": {"id": "minecraft:oak_planks", "count": 4}}


def _errors(packs):
    return sorted((e.path.rsplit("/", 1)[-1], e.line, e.col, e.message) for e in packs.errors)


def test_a_recipe_that_decodes_keeps_its_body(tmp_path):
    shapeless = {"type": "crafting_shapeless", "ingredients": [{"tag": "minecraft:logs"}, [{"item": "stone"}]],
                 "result": {"id": "minecraft:stone", "components": {"minecraft:custom_data": {"a": 1}}}}
    root = write_pack(tmp_path / "p", {"a/recipe/shaped.json": json.dumps(SHAPED),
                                       "a/recipe/shapeless.json": json.dumps(shapeless),
                                       "a/recipe/smelt.json": json.dumps(SMELT)})
    packs = load_packs([root], mc_version="1.21")
    assert packs.errors == []
    assert set(packs.recipe_bodies) == {"a:shaped", "a:shapeless", "a:smelt"}
    assert packs.recipes["a:shaped"] == "minecraft:crafting_shaped"


def test_shaped_problems_at_their_place(tmp_path):
    text = json.dumps({"type": "minecraft:crafting_shaped", "pattern": ["#X", "# "],
                       "key": {"#": {"item": "minecraft:stick"}, "Y": {"item": "minecraft:stone"}},
                       "result": {"id": "minecraft:stick", "count": 100}}, indent=1)
    root = write_pack(tmp_path / "p", {"a/recipe/bad.json": text, "a/recipe/good.json": json.dumps(SHAPED),
                                       "a/recipe/wide.json": json.dumps({**SHAPED, "pattern": ["####"]}),
                                       "a/recipe/ragged.json": json.dumps({**SHAPED, "pattern": ["##", "#"]})})
    packs = load_packs([root], mc_version="1.21")
    assert _errors(packs) == [
        ("bad.json", 4, 3, "pattern references symbol 'X' but it's not defined in the key"),
        ("bad.json", 11, 3, "key defines symbol 'Y' that the pattern does not use"),
        ("bad.json", 17, 3, "the result's \"count\" is a whole number from 1 to 99"),
        ("ragged.json", 1, 57, "invalid pattern: each row must be the same width"),
        ("wide.json", 1, 51, "invalid pattern: too many columns, 3 is maximum")]
    # RecipeManager skips them: they do not exist (``recipe give`` fails on them)
    assert set(packs.recipe_bodies) == set(packs.recipes) == {"a:good"}


def test_ingredients_and_results_by_release(tmp_path):
    # 1.21.2 reads an ingredient as an id, a '#tag' or a list of ids; before, {"item"} / {"tag"}
    new = {"type": "minecraft:crafting_shapeless", "ingredients": ["minecraft:stick", "#minecraft:logs",
                                                                  ["minecraft:stone", "minecraft:dirt"]],
           "result": {"id": "minecraft:stick"}}
    root = write_pack(tmp_path / "p", {"a/recipe/new.json": json.dumps(new)})
    assert load_packs([root], mc_version="1.21.4").errors == []
    old = load_packs([root], mc_version="1.21")
    assert [e.message for e in old.errors] == [
        'an ingredient is {"item": id} or {"tag": id}, or a list of them (before 1.21.2)'] * 4
    assert "a:new" not in old.recipe_bodies
    # before 1.20.5 the result names its ``item``; an unknown item is refused
    legacy = {"type": "minecraft:crafting_shapeless", "ingredients": [{"item": "minecraft:stick"}],
              "result": {"item": "minecraft:not_an_item"}}
    root = write_pack(tmp_path / "q", {"a/recipes/legacy.json": json.dumps(legacy)})
    (root / "pack.mcmeta").write_text(json.dumps({"pack": {"pack_format": 26, "description": ""}}))
    assert [e.message for e in load_packs([root]).errors] == ["unknown item 'minecraft:not_an_item'"]


def test_unknown_and_retired_types(tmp_path):
    root = write_pack(tmp_path / "p", {"a/recipe/x.json": json.dumps({"type": "minecraft:crafting_fancy"}),
                                       "a/recipe/y.json": json.dumps({"type": "crafting_special_shulkerboxcoloring"}),
                                       "a/recipe/t.json": json.dumps({"type": "crafting_transmute"})})
    assert [e.message for e in load_packs([root], mc_version="1.21.4").errors] == [
        "recipe type 'minecraft:crafting_fancy' is not a recipe type known to dpemu",
        "recipe type 'crafting_special_shulkerboxcoloring' is not a recipe type in this version"]
    assert [e.message for e in load_packs([root], mc_version="1.21").errors] == [
        "recipe type 'crafting_transmute' is not a recipe type in this version",
        "recipe type 'minecraft:crafting_fancy' is not a recipe type known to dpemu"]


def test_cooking_recipes_by_release(tmp_path):
    # AbstractCookingRecipe.Serializer: an ingredient and a result, an item id before 1.20.5
    # (GsonHelper.getAsString; the item registry's codec from 1.20.2), then
    # ItemStack.STRICT_SINGLE_ITEM_CODEC: {id, components}, a count not read; experience and
    # cookingtime default (decompiled 1.20.2 and 1.21 AbstractCookingRecipe.Serializer)
    root = write_pack(tmp_path / "p", {
        "a/recipe/good.json": json.dumps({**SMELT, "type": "minecraft:blasting", "result": {"id": "stone", "count": 300}}),
        "a/recipe/no_result.json": json.dumps({"type": "minecraft:smoking", "ingredient": {"item": "minecraft:beef"}}),
        "a/recipe/old_result.json": json.dumps({**SMELT, "result": "minecraft:stone"}),
        "a/recipe/no_ingredient.json": json.dumps({"type": "campfire_cooking", "result": {"id": "minecraft:cooked_beef"}})})
    packs = load_packs([root], mc_version="1.21")
    assert [(e.path.rsplit("/", 1)[-1], e.message) for e in packs.errors] == [
        ("no_ingredient.json", 'a cooking recipe needs "ingredient"'),
        ("no_result.json", 'a cooking recipe needs "result": an object with the item\'s "id"'),
        ("old_result.json", 'a cooking recipe needs "result": an object with the item\'s "id"')]
    assert set(packs.recipe_bodies) == {"a:good"}
    old = write_pack(tmp_path / "q", {"a/recipes/old.json": json.dumps({**SMELT, "result": "minecraft:stone"}),
                                      "a/recipes/new.json": json.dumps(SMELT)})
    (old / "pack.mcmeta").write_text(json.dumps({"pack": {"pack_format": 26, "description": ""}}))
    assert [e.message for e in load_packs([old]).errors] == [
        'a cooking recipe needs "result": an item id (before 1.20.5)']
