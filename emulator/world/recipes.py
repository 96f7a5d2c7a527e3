"""The players' recipe books: which recipes each player knows, kept in its saved ``recipeBook`` as
the game saves it, so ``data get`` and ``nbt=`` read what ``recipe give|take``, advancement rewards
and knowledge books change.

- ``EMPTY_BOOK()``: a new player's ``recipeBook`` (ServerRecipeBook.toNbt: the book settings'
  eight flags, ``recipes`` and ``toBeDisplayed``).
- ``find(resources, recipe_id)``: whether the recipe exists (the packs', or the game's from its
  jar); a ``minecraft:`` recipe no pack defines is not modelled without the game's data.
- ``every(resources)``: every recipe (``recipe give|take ... *``; not modelled without the jar).
- ``award(player, recipe_ids, resources, unlocked) -> int`` / ``revoke(player, recipe_ids) -> int``:
  ServerRecipeBook.addRecipes / removeRecipes: the number of recipes added or removed; ``unlocked(id)``
  hears each recipe added (the ``recipe_unlocked`` trigger).

Sources (decompiled 1.21): stats/ServerRecipeBook.java (addRecipes: a recipe already known or
special is skipped, the others are added, highlighted and fire RECIPE_UNLOCKED; removeRecipes:
the known ones, their highlight kept as the game keeps it; toNbt), stats/RecipeBookSettings.java
(write: isGuiOpen/isFilteringCraftable, isFurnace..., isBlastingFurnace..., isSmoker...),
world/item/crafting/CustomRecipe.java and MapExtendingRecipe.java (isSpecial: the
``crafting_special_*`` types and ``crafting_decorated_pot``). The game keeps the ids in a hash
set, so its list order is the set's; here it is the order they were added.
"""
from __future__ import annotations

from typing import Callable

from emulator.world.errors import CommandFailure, Unmodelled
from mcfunction_parser.nbt import Byte, Compound, List, String

_SETTINGS = ("isGuiOpen", "isFilteringCraftable", "isFurnaceGuiOpen", "isFurnaceFilteringCraftable",
             "isBlastingFurnaceGuiOpen", "isBlastingFurnaceFilteringCraftable", "isSmokerGuiOpen",
             "isSmokerFilteringCraftable")


def EMPTY_BOOK() -> Compound:  # noqa: N802 (a constant made fresh each time)
    book = Compound((name, Byte(0)) for name in _SETTINGS)
    book["recipes"] = List()
    book["toBeDisplayed"] = List()
    return book


def _book(player) -> Compound:
    book = player.data.get("recipeBook")
    if not isinstance(book, Compound):
        book = player.data["recipeBook"] = EMPTY_BOOK()
    for key in ("recipes", "toBeDisplayed"):
        if not isinstance(book.get(key), List):
            book[key] = List()
    return book


def known(player) -> list[str]:
    return [str(r) for r in _book(player)["recipes"]]


def find(resources, recipe_id: str) -> bool:
    """Whether recipe ``recipe_id`` exists; the game's own are known only from its jar."""
    if recipe_id in resources.recipes:
        return True
    if recipe_id.startswith("minecraft:") and not resources.vanilla_data:
        raise Unmodelled(f"the game's own recipe {recipe_id} is not known without the game's data (pass --game-jar)")
    return False


def every(resources) -> list[str]:
    """Every recipe (RecipeManager.getRecipes), which includes the game's own: not modelled without them."""
    if not resources.vanilla_data:
        raise Unmodelled("every recipe ('*'): the game's own recipes are not known without the game's data "
                         "(pass --game-jar)")
    return list(resources.recipes)


def _is_special(kind: str) -> bool:
    return kind.startswith("minecraft:crafting_special_") or kind == "minecraft:crafting_decorated_pot"


def award(player, recipe_ids: list[str], resources, unlocked: Callable[[str], None]) -> int:
    """ServerRecipeBook.addRecipes: each recipe neither known nor special is added to ``recipes``
    and ``toBeDisplayed`` and heard by ``unlocked``; the number added."""
    book, added = _book(player), 0
    for recipe_id in recipe_ids:
        if recipe_id in known(player) or _is_special(resources.recipes.get(recipe_id, "")):
            continue
        book["recipes"].append(String(recipe_id))
        if recipe_id not in map(str, book["toBeDisplayed"]):
            book["toBeDisplayed"].append(String(recipe_id))
        unlocked(recipe_id)
        added += 1
    return added


def revoke(player, recipe_ids: list[str]) -> int:
    """ServerRecipeBook.removeRecipes: each known recipe leaves ``recipes`` (RecipeBook.remove
    drops its highlight too); the number removed."""
    book, removed = _book(player), 0
    for recipe_id in recipe_ids:
        if recipe_id in known(player):
            for key in ("recipes", "toBeDisplayed"):
                book[key] = List(r for r in book[key] if str(r) != recipe_id)
            removed += 1
    return removed


def unknown_recipe(recipe_id: str) -> CommandFailure:
    """ResourceLocationArgument.getRecipe's failure."""
    return CommandFailure("recipe.notFound", recipe_id)
