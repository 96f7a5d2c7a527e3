"""Crafting: which recipe a 3x3 grid of stacks makes, and what it gives, as the game's crafting
recipes match and assemble.

- ``craft(resources, grid, version) -> Crafted | None``: the first loaded recipe that matches the
  grid (nine stacks, row by row) and its result and remainders; None when none matches.
  A shaped (``crafting_shaped``) or shapeless (``crafting_shapeless``) recipe is matched; when
  none of them matches and a recipe the emulator does not match could (the game's own recipes
  without ``--game-jar``, a special or transmute recipe), the craft is not modelled (Unmodelled).

Rules (decompiled 1.21): CraftingInput.ofPositioned (the grid trimmed to the box around its
stacks), ShapedRecipePattern (unpack: the pattern trimmed of empty rows and columns; matches: the
same number of stacks, the same size, the pattern or its mirror), ShapelessRecipe.matches (as many
stacks as ingredients, each stack used by one ingredient: StackedContents.canCraft),
Ingredient.test (the item only, never its components; an empty ingredient holds only the empty
stack), ShapedRecipe/ShapelessRecipe.assemble (a copy of the result: ItemStack.STRICT_CODEC,
``item`` before 1.20.5), CraftingRecipe.getRemainingItems (Item.getCraftingRemainingItem: the
water, lava and milk buckets leave a bucket, honey bottles and dragon's breath a glass bottle),
RecipeManager.getRecipeFor (the first recipe of the type that matches; the game's order is its
recipe map's, here the packs' load order).
"""
from __future__ import annotations

from dataclasses import dataclass

from emulator.world import items
from emulator.world.errors import Unmodelled
from emulator.world.items import ItemStack
from emulator.world.loot_context import namespaced as _id, to_tag

SHAPED, SHAPELESS = "minecraft:crafting_shaped", "minecraft:crafting_shapeless"
# the crafting recipe types (RecipeType.CRAFTING) the emulator does not match
UNMATCHED_PREFIXES = ("minecraft:crafting_special_", "minecraft:crafting_decorated_pot", "minecraft:crafting_transmute")
REMAINDERS = {f"minecraft:{full}": f"minecraft:{left}" for full, left in (
    ("water_bucket", "bucket"), ("lava_bucket", "bucket"), ("milk_bucket", "bucket"),
    ("honey_bottle", "glass_bottle"), ("dragon_breath", "glass_bottle"))}


@dataclass
class Crafted:
    recipe_id: str
    result: ItemStack
    remainders: list[ItemStack]  # one per stack of the trimmed grid, empty where nothing is left


def trimmed(grid: list[ItemStack], width: int = 3) -> tuple[int, int, list[ItemStack]]:
    """CraftingInput.ofPositioned: the smallest box holding every stack (0 x 0 when none)."""
    cells = [(i % width, i // width) for i, stack in enumerate(grid) if not stack.is_empty]
    if not cells:
        return 0, 0, []
    left, right = min(x for x, _ in cells), max(x for x, _ in cells)
    top, bottom = min(y for _, y in cells), max(y for _, y in cells)
    return (right - left + 1, bottom - top + 1,
            [grid[x + y * width] for y in range(top, bottom + 1) for x in range(left, right + 1)])


def _ingredient_test(ingredient, stack: ItemStack, resources) -> bool:
    """Ingredient.test: ``None`` is the empty ingredient; a value is an id, ``#tag``, ``{"item"}``,
    ``{"tag"}`` or a list of them (the release's form was checked when the recipe loaded)."""
    if ingredient is None:
        return stack.is_empty
    if stack.is_empty:
        return False
    for value in ingredient if isinstance(ingredient, list) else [ingredient]:
        if isinstance(value, dict):
            value = value.get("item", "#" + str(value.get("tag", "")))
        if value.startswith("#"):
            if resources.in_tag("item", _id(value[1:]), stack.id):
                return True
        elif _id(value) == stack.id:
            return True
    return False


def _shrunk_pattern(pattern: list[str]) -> list[str]:
    """ShapedRecipePattern.shrink: the rows and columns of spaces around the symbols removed."""
    rows = [i for i, row in enumerate(pattern) if row.strip(" ")]
    if not rows:
        return []
    left = min(len(r) - len(r.lstrip(" ")) for r in pattern if r.strip(" "))
    right = max(len(r.rstrip(" ")) for r in pattern)
    return [row[left:right] for row in pattern[rows[0]:rows[-1] + 1]]


def _shaped_matches(recipe: dict, width: int, height: int, stacks: list[ItemStack], resources) -> bool:
    pattern = _shrunk_pattern(recipe["pattern"])
    cells = [None if c == " " else recipe["key"][c] for row in pattern for c in row]
    p_width = len(pattern[0]) if pattern else 0
    if sum(c is not None for c in cells) != sum(not s.is_empty for s in stacks):
        return False
    if (p_width, len(pattern)) != (width, height):
        return False

    def fits(mirrored: bool) -> bool:
        return all(_ingredient_test(cells[(width - x - 1 if mirrored else x) + y * width], stacks[x + y * width],
                                    resources) for y in range(height) for x in range(width))
    return fits(True) or fits(False)


def _shapeless_matches(recipe: dict, stacks: list[ItemStack], resources) -> bool:
    """Every stack used by a different ingredient (a matching of the bipartite graph)."""
    present = [s for s in stacks if not s.is_empty]
    ingredients = recipe["ingredients"]
    if len(present) != len(ingredients):
        return False
    fits = [[i for i, ing in enumerate(ingredients) if _ingredient_test(ing, s, resources)] for s in present]
    taken: dict[int, int] = {}

    def place(stack: int, seen: set[int]) -> bool:
        for i in fits[stack]:
            if i not in seen:
                seen.add(i)
                if i not in taken or place(taken[i], seen):
                    taken[i] = stack
                    return True
        return False
    return all(place(s, set()) for s in range(len(present)))


def result_stack(result: dict, version) -> ItemStack:
    """ItemStack.STRICT_CODEC's result (``id``, ``count``, ``components``), ``item`` before 1.20.5."""
    if tuple(version) < items.COMPONENTS_VERSION:
        return ItemStack(_id(result["item"]), int(result.get("count", 1)))
    stack = ItemStack(_id(result["id"]), int(result.get("count", 1)))
    for name, value in (result.get("components") or {}).items():
        if name.startswith("!"):
            items.remove_component(stack, _id(name[1:]))
        else:
            items.set_component(stack, _id(name), to_tag(value))
    return stack


def craft(resources, grid: list[ItemStack], version) -> Crafted | None:
    width, height, stacks = trimmed(grid)
    if not stacks:
        return None
    unmatched = []
    for recipe_id, kind in resources.recipes.items():
        body = resources.recipe_bodies.get(recipe_id)
        if kind == SHAPED and body is not None:
            found = _shaped_matches(body, width, height, stacks, resources)
        elif kind == SHAPELESS and body is not None:
            found = _shapeless_matches(body, stacks, resources)
        else:
            if kind.startswith(UNMATCHED_PREFIXES):
                unmatched.append(recipe_id)
            continue
        if found:
            remainders = [ItemStack(REMAINDERS[s.id]) if s.id in REMAINDERS else items.EMPTY.copy() for s in stacks]
            return Crafted(recipe_id, result_stack(body["result"], version), remainders)
    if not resources.vanilla_data:
        raise Unmodelled("crafting with no pack recipe matching: the game's own recipes are not known without "
                         "the game's data (pass --game-jar)")
    if unmatched:
        raise Unmodelled(f"crafting with no shaped or shapeless recipe matching: {unmatched[0]} "
                         f"({resources.recipes[unmatched[0]]}) may match, which the emulator does not model")
    return None
