"""Recipe JSON as the game decodes it (``data/<ns>/recipe/<path>.json``, ``recipes/`` before 1.21):
the recipe types per release and the fields of the recipes the emulator runs (shaped, shapeless
and the cooking recipes). A recipe that does not decode is skipped by the game ("Parsing error loading recipe"),
so the loader keeps only the recipes that pass; each problem is a diagnostic at its JSON string.

- ``check_recipe(doc, version, diagnostics) -> bool``: True when the recipe would load.
- ``RECIPE_TYPES``: type -> (first release, first release without it). A type missing from the
  table is an error up to 1.21.11 and a warning after it (a later release may add types).
- ``ingredient_strings(version)``: whether ingredients are written as item ids, ``#tags`` or lists
  of ids (1.21.2+), rather than ``{"item": id}`` / ``{"tag": id}`` objects or lists of them.

Sources: decompiled 1.21 world/item/crafting/RecipeSerializer.java (the types), ShapedRecipe and
ShapedRecipePattern (``key``: one-character symbols other than a space, each an ingredient that is
not empty; ``pattern``: 1 to 3 rows of the same width, 1 to 3 columns; every symbol of the
pattern in the key and every key symbol used), ShapelessRecipe (1 to 9 ingredients), Ingredient
(CODEC: a value or a non-empty list of values, each ``{"item"}`` xor ``{"tag"}``),
ItemStack.STRICT_CODEC (the ``result``: ``id``, ``count`` 1 - 99, ``components``; ``item`` and
``count`` before 1.20.5), AbstractCookingRecipe.Serializer (1.20.2 and 1.20.5); the 1.21.2 ingredient and crafting_transmute changes from the
minecraft.wiki "Recipe" page (history).
"""
from __future__ import annotations

from typing import Any

from mcfunction_parser.diagnostics import ERROR, WARNING, Diagnostic
from mcfunction_parser.pack.loot import _Checker, _typed, known
from mcfunction_parser.pack.text import JsonDocument

Version = tuple[int, int, int]
_ALWAYS = ((1, 13, 0), None)
COMPONENTS_VERSION = (1, 20, 5)
INGREDIENT_STRINGS = (1, 21, 2)
NEWEST_KNOWN = (1, 21, 11)  # the newest release whose recipe types this table is sure of

RECIPE_TYPES = {
    **{f"minecraft:{n}": _ALWAYS for n in (
        "crafting_shaped crafting_shapeless smelting crafting_special_armordye crafting_special_bookcloning "
        "crafting_special_mapcloning crafting_special_mapextending crafting_special_firework_rocket "
        "crafting_special_firework_star crafting_special_firework_star_fade crafting_special_repairitem "
        "crafting_special_tippedarrow crafting_special_bannerduplicate crafting_special_shielddecoration").split()},
    "minecraft:crafting_special_shulkerboxcoloring": ((1, 13, 0), (1, 21, 2)),
    "minecraft:crafting_special_banneraddpattern": ((1, 13, 0), (1, 14, 0)),
    **{f"minecraft:{n}": ((1, 14, 0), None) for n in
       "blasting smoking campfire_cooking stonecutting crafting_special_suspiciousstew".split()},
    "minecraft:smithing": ((1, 16, 0), (1, 20, 0)),
    "minecraft:smithing_transform": ((1, 19, 4), None),
    "minecraft:smithing_trim": ((1, 19, 4), None),
    "minecraft:crafting_decorated_pot": ((1, 20, 0), None),
    "minecraft:crafting_transmute": (INGREDIENT_STRINGS, None),
}


COOKING_TYPES = frozenset(f"minecraft:{n}" for n in "smelting blasting smoking campfire_cooking".split())


def ingredient_strings(version: Version) -> bool:
    return tuple(version) >= INGREDIENT_STRINGS


class _RecipeChecker(_Checker):
    def recipe(self, root: Any, recipe_id: str) -> None:
        if not isinstance(root, dict):
            self.report(ERROR, "a recipe must be a JSON object", None)
            return
        raw = root.get("type")
        if not isinstance(raw, str):
            self.report(ERROR, 'a recipe needs the string "type"', "type")
            return
        kind = _typed(raw)
        self.advance(raw)
        if not known(RECIPE_TYPES, kind, self.version):
            where = "in this version" if kind in RECIPE_TYPES else "known to dpemu"
            severity = ERROR if self.version <= NEWEST_KNOWN or kind in RECIPE_TYPES else WARNING
            self.report(severity, f"recipe type '{raw}' is not a recipe type {where}", raw)
            return
        if kind == "minecraft:crafting_shaped":
            self.shaped(root)
        elif kind == "minecraft:crafting_shapeless":
            self.shapeless(root)
        elif kind in COOKING_TYPES:
            self.cooking(root)
            return
        else:
            return
        self.result(root.get("result"))

    def cooking(self, root: dict) -> None:
        """AbstractCookingRecipe's serializer: an ``ingredient`` and a ``result``: an item id before
        1.20.5 (GsonHelper.getAsString, then the item registry's codec from 1.20.2), from 1.20.5
        ItemStack.STRICT_SINGLE_ITEM_CODEC (``id`` and ``components``; a ``count`` is not read);
        ``experience`` and ``cookingtime`` have defaults."""
        if "ingredient" not in root:
            self.report(ERROR, 'a cooking recipe needs "ingredient"', "type")
        else:
            self.advance("ingredient")
            self.ingredient(root["ingredient"])
        result = root.get("result")
        if self.version < COMPONENTS_VERSION:
            if not isinstance(result, str):
                self.report(ERROR, 'a cooking recipe needs "result": an item id (before 1.20.5)', "result")
            else:
                self.item(result)
        elif not isinstance(result, dict) or not isinstance(result.get("id"), str):
            self.report(ERROR, 'a cooking recipe needs "result": an object with the item\'s "id"', "result")
        else:
            self.item(result["id"])
            for name in result.get("components", {}) if isinstance(result.get("components"), dict) else ():
                self.component(name)

    def shaped(self, root: dict) -> None:
        """The key, then the pattern, each searched from the recipe's start (either comes first)."""
        key, pattern = root.get("key"), root.get("pattern")
        start = self.cursor
        if not isinstance(key, dict):
            self.report(ERROR, 'a shaped recipe needs "key": an object of symbols', "key")
            return
        self.advance("key")
        for symbol, ingredient in key.items():
            if len(symbol) != 1:
                self.report(ERROR, f"invalid key entry '{symbol}': a symbol is one character", symbol)
            elif symbol == " ":
                self.report(ERROR, "invalid key entry: ' ' is a reserved symbol", symbol)
            self.advance(symbol)
            self.ingredient(ingredient)
        end, self.cursor = self.cursor, start
        if not isinstance(pattern, list) or not all(isinstance(row, str) for row in pattern):
            self.report(ERROR, 'a shaped recipe needs "pattern": a list of strings', "pattern")
            return
        self.advance("pattern")
        if not pattern:
            self.report(ERROR, "invalid pattern: empty pattern not allowed", "pattern")
        elif len(pattern) > 3:
            self.report(ERROR, "invalid pattern: too many rows, 3 is maximum", pattern[3])
        elif any(len(row) > 3 for row in pattern):
            self.report(ERROR, "invalid pattern: too many columns, 3 is maximum", next(r for r in pattern if len(r) > 3))
        elif len({len(row) for row in pattern}) > 1:
            self.report(ERROR, "invalid pattern: each row must be the same width", pattern[-1])
        used = {c for row in pattern for c in row if c != " "}
        for symbol in sorted(used - set(key)):
            self.report(ERROR, f"pattern references symbol '{symbol}' but it's not defined in the key",
                        next(r for r in pattern if symbol in r))
        self.cursor = start
        self.advance("key")
        for symbol in [s for s in key if s not in used and len(s) == 1 and s != " "]:
            self.report(ERROR, f"key defines symbol '{symbol}' that the pattern does not use", symbol)
        self.cursor = max(self.cursor, end)

    def shapeless(self, root: dict) -> None:
        ingredients = root.get("ingredients")
        if not isinstance(ingredients, list):
            self.report(ERROR, 'a shapeless recipe needs "ingredients": a list', "ingredients")
            return
        self.advance("ingredients")
        if not ingredients:
            self.report(ERROR, "no ingredients for shapeless recipe", "ingredients")
        elif len(ingredients) > 9:
            self.report(ERROR, "too many ingredients for shapeless recipe (9 at most)", "ingredients")
        for ingredient in ingredients:
            self.ingredient(ingredient)

    def ingredient(self, value: Any) -> None:
        """Ingredient.CODEC_NONEMPTY of the release."""
        if isinstance(value, list):
            if not value:
                self.report(ERROR, "an ingredient list cannot be empty, at least one item must be defined", None)
            for one in value:
                self.ingredient_value(one, in_list=True)
        else:
            self.ingredient_value(value, in_list=False)

    def ingredient_value(self, value: Any, in_list: bool) -> None:
        if ingredient_strings(self.version):
            if isinstance(value, str) and not (in_list and value.startswith("#")):
                if not value.startswith("#"):
                    self.item(value)
                return
            token = value if isinstance(value, str) else value.get("item", value.get("tag")) if isinstance(value, dict) else None
            self.report(ERROR, "an ingredient is an item id, a '#tag' or a list of item ids (1.21.2+)",
                        token if isinstance(token, str) else None)
            return
        if isinstance(value, dict) and ("item" in value) != ("tag" in value):
            if isinstance(value.get("item"), str):
                self.item(value["item"])
                return
            if isinstance(value.get("tag"), str):
                self.advance(value["tag"])
                return
        self.report(ERROR, 'an ingredient is {"item": id} or {"tag": id}, or a list of them (before 1.21.2)',
                    value if isinstance(value, str) else None)

    def result(self, result: Any) -> None:
        """ItemStack.STRICT_CODEC (1.20.5+: ``id``, ``count``, ``components``) or ``item``, ``count``."""
        key = "id" if self.version >= COMPONENTS_VERSION else "item"
        if not isinstance(result, dict) or not isinstance(result.get(key), str):
            self.report(ERROR, f'a recipe needs "result": an object with the item\'s "{key}"', "result")
            return
        self.item(result[key])
        count = result.get("count", 1)
        if not isinstance(count, int) or isinstance(count, bool) or not 1 <= count <= 99:
            self.report(ERROR, 'the result\'s "count" is a whole number from 1 to 99', "count")
        components = result.get("components", {})
        if key == "id" and isinstance(components, dict):
            for name in components:
                self.component(name)


def check_recipe(doc: JsonDocument, version: Version, recipe_id: str, diagnostics: list[Diagnostic]) -> bool:
    checker = _RecipeChecker(doc, tuple(version), diagnostics)
    checker.recipe(doc.value, recipe_id)
    return checker.ok
