"""Crafting: which recipe a 3x3 grid of stacks makes, and what it gives, as the game's crafting
recipes match and assemble.

- ``craft(resources, grid, version) -> Crafted | None``: the first recipe in the game's order
  (``recipe_order``) that matches the grid (nine stacks, row by row), its result and remainders;
  None when none matches. Shaped (``crafting_shaped``), shapeless (``crafting_shapeless``),
  transmute (from 1.21.2; from 1.21.5 with its result's count and components), and before 26.1 book
  cloning, firework rockets and tipped arrows (from 1.20.5) and map cloning recipes, and shulker
  box colouring from 1.20.5 to 1.21.1, are matched; another special recipe
  (``crafting_special_*``, ``crafting_decorated_pot``) reached in that order, when the grid
  holds what it needs, makes the craft not modelled (Unmodelled), as does no match without the
  game's own recipes (``--game-jar``) and, before 1.21.2 without them, two matches.

Rules (decompiled 1.21): CraftingInput.ofPositioned (the grid trimmed to the box around its
stacks), ShapedRecipePattern (unpack: the pattern trimmed of empty rows and columns; matches: the
same number of stacks, the same size, the pattern or its mirror), ShapelessRecipe.matches (as many
stacks as ingredients, each stack used by one ingredient: StackedContents.canCraft),
Ingredient.test (the item only, never its components; an empty ingredient holds only the empty
stack), ShapedRecipe/ShapelessRecipe.assemble (a copy of the result: ItemStack.STRICT_CODEC,
``item`` before 1.20.5), CraftingRecipe.getRemainingItems (Item.getCraftingRemainingItem: the
water, lava and milk buckets leave a bucket, honey bottles and dragon's breath a glass bottle),
RecipeManager.getRecipeFor (the first recipe of the type that matches, in the recipe map's order),
TransmuteRecipe (1.21.3: matches, assemble, ItemStack.transmuteCopy; 1.21.11: matches with
TransmuteResult.isResultUnchanged, assemble with TransmuteResult.apply and its CODEC), BookCloningRecipe
(matches, assemble, getRemainingItems; WrittenBookContent.tryCraftCopy), MapCloningRecipe,
FireworkRocketRecipe, TippedArrowRecipe, ShulkerBoxColoring, the other special recipes' matches (what each needs in the grid).
"""
from __future__ import annotations

from dataclasses import dataclass

from emulator.world import items
from emulator.world.errors import Unmodelled
from emulator.world.hash_order import java_hash_map_order, resource_location_hash
from emulator.world.id_families import COLOURS
from emulator.world.inventories import SHULKER_BOXES
from emulator.world.items import ItemStack
from emulator.world.loot_context import component_tag, namespaced as _id
from emulator.world.nbt_ops import is_numeric, numeric_value
from mcfunction_parser.nbt import Byte, Compound, Int, List

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


def ingredient_test(ingredient, stack: ItemStack, resources) -> bool:
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
        return all(ingredient_test(cells[(width - x - 1 if mirrored else x) + y * width], stacks[x + y * width],
                                    resources) for y in range(height) for x in range(width))
    return fits(True) or fits(False)


def _shapeless_matches(recipe: dict, stacks: list[ItemStack], resources) -> bool:
    """Every stack used by a different ingredient (a matching of the bipartite graph)."""
    present = [s for s in stacks if not s.is_empty]
    ingredients = recipe["ingredients"]
    if len(present) != len(ingredients):
        return False
    fits = [[i for i, ing in enumerate(ingredients) if ingredient_test(ing, s, resources)] for s in present]
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
            items.set_component(stack, _id(name), component_tag(_id(name), value))
    return stack


# RecipeManager.prepare from 1.21.2 keeps the recipes in a TreeMap; before, apply walked a HashMap
SORTED_RECIPES = (1, 21, 2)
TRANSMUTE, TRANSMUTE_SINCE, TRANSMUTE_REWRITTEN = "minecraft:crafting_transmute", (1, 21, 2), (1, 21, 5)


def recipe_order(ids, version) -> list[str]:
    """The order RecipeManager.getRecipeFor tries recipes in (its ``byType`` multimap keeps the
    order the recipes were read in). From 1.21.2 RecipeManager.prepare reads them from a TreeMap:
    by id (ResourceLocation.compareTo: the path, then the namespace). Before, ``apply`` walked the
    HashMap SimpleJsonResourceReloadListener.prepare filled with the files in TreeMap order of their
    locations (``<ns>:recipe/<path>.json``): :func:`emulator.world.hash_order.java_hash_map_order`."""
    def by_location(rid: str, suffix: str = "") -> tuple[str, str]:
        namespace, _, path = rid.partition(":")
        return path + suffix, namespace
    if tuple(version) >= SORTED_RECIPES:
        return sorted(ids, key=by_location)
    return java_hash_map_order(sorted(ids, key=lambda rid: by_location(rid, ".json")), resource_location_hash)


def _transmute_result(recipe: dict) -> tuple[str, int, dict]:
    """TransmuteResult.CODEC (1.21.5+): an item id, or ``{id, count, components}`` (count 1 and no
    components by default)."""
    result = recipe.get("result", "")
    if isinstance(result, dict):
        return _id(str(result.get("id", ""))), int(result.get("count", 1)), result.get("components") or {}
    return _id(str(result)), 1, {}


def _transmute_copy(source: ItemStack, item_id: str, count: int) -> ItemStack:
    """ItemStack.transmuteCopy: the item changed, the source's component patch kept over it."""
    made = ItemStack(item_id, count)
    for name, value in source.patch.items():
        if name.startswith("!"):
            items.remove_component(made, name[1:])
        else:
            items.set_component(made, name, value)
    return made


def _transmute_applied(recipe: dict, source: ItemStack) -> ItemStack:
    """TransmuteResult.apply: transmuteCopy to the result's item and count, then its components."""
    item_id, count, components = _transmute_result(recipe)
    made = _transmute_copy(source, item_id, count)
    for name, value in components.items():
        if name.startswith("!"):
            items.remove_component(made, _id(name[1:]))
        else:
            items.set_component(made, _id(name), component_tag(_id(name), value))
    return made


def _transmuted_since_1_21_5(recipe: dict, stacks: list[ItemStack], resources) -> ItemStack | None:
    """TransmuteRecipe (1.21.5+): two stacks; the first that the input accepts is the input, and the
    recipe does not match when the result would leave it unchanged (TransmuteResult.isResultUnchanged:
    one item, the same item and components); every other stack must be the one material. The
    result is TransmuteResult.apply of the input. None when it does not match."""
    present = [s for s in stacks if not s.is_empty]
    if len(present) != 2:
        return None
    source, material = None, False
    for stack in present:
        if source is None and ingredient_test(recipe.get("input"), stack, resources):
            made = _transmute_applied(recipe, stack)
            if made.count == 1 and made.same_item_same_components(stack):
                return None
            source = stack
        elif material or not ingredient_test(recipe.get("material"), stack, resources):
            return None
        else:
            material = True
    return _transmute_applied(recipe, source) if source is not None and material else None


def _transmuted(recipe: dict, stacks: list[ItemStack], resources) -> ItemStack | None:
    """TransmuteRecipe (1.21.2 - 1.21.4): two stacks, the input (not already the result) and the
    material; the result is the input's item made the result item, one of it, with the input's
    components (ItemStack.transmuteCopy). None when it does not match."""
    result = _id(str(recipe.get("result", "")))
    present = [s for s in stacks if not s.is_empty]
    if len(present) != 2:
        return None
    source, material = None, False
    for stack in present:
        if source is None and ingredient_test(recipe.get("input"), stack, resources) and stack.id != result:
            source = stack
        elif material or not ingredient_test(recipe.get("material"), stack, resources):
            return None
        else:
            material = True
    if source is None or not material:
        return None
    return _transmute_copy(source, result, 1)


# each special recipe type the emulator does not match, and an item it cannot match without (the
# recipes' matches methods: CraftingInput needs that item): a grid without it is no such craft
_SPECIAL_NEEDS = {f"minecraft:crafting_special_{kind}": need for kind, need in {
    "armordye": lambda ids: any(i.endswith("_dye") for i in ids),
    "bookcloning": lambda ids: "minecraft:written_book" in ids,
    "mapcloning": lambda ids: "minecraft:filled_map" in ids,
    "mapextending": lambda ids: "minecraft:filled_map" in ids,
    "firework_rocket": lambda ids: "minecraft:paper" in ids,
    "firework_star": lambda ids: "minecraft:gunpowder" in ids,
    "firework_star_fade": lambda ids: "minecraft:firework_star" in ids,
    "repairitem": lambda ids: len(ids) == 2,
    "tippedarrow": lambda ids: "minecraft:lingering_potion" in ids,
    "bannerduplicate": lambda ids: sum(i.endswith("_banner") for i in ids) >= 2,
    "shielddecoration": lambda ids: "minecraft:shield" in ids,
    "shulkerboxcoloring": lambda ids: any(i.endswith("shulker_box") for i in ids),
    "suspiciousstew": lambda ids: "minecraft:bowl" in ids,
}.items()}
_SPECIAL_NEEDS["minecraft:crafting_decorated_pot"] = lambda ids: len(ids) == 4


def _may_match(kind: str, recipe: dict | None, stacks: list[ItemStack], resources) -> bool:
    """Whether a recipe the emulator does not match could match these stacks (False only when the
    grid lacks what it needs: a later transmute's every stack is its input or material)."""
    ids = [s.id for s in stacks if not s.is_empty]
    if kind == TRANSMUTE:
        return recipe is None or len(ids) >= 2 and all(
            ingredient_test(recipe.get("input"), s, resources) or ingredient_test(recipe.get("material"), s, resources)
            for s in stacks if not s.is_empty)
    need = _SPECIAL_NEEDS.get(kind)
    return need is None or need(ids)


# the special recipes matched here, until 26.1 made them data-driven (its forms are not modelled)
BOOK_CLONING, MAP_CLONING = "minecraft:crafting_special_bookcloning", "minecraft:crafting_special_mapcloning"
SPECIAL_UNTIL = (26, 1, 0)
WRITTEN_BOOK = "minecraft:written_book"


def _cloned(stacks: list[ItemStack], source_id: str, material_id: str) -> tuple[ItemStack, int] | None:
    """BookCloningRecipe / MapCloningRecipe.matches: one source stack and at least one material,
    nothing else; (the source, how many materials)."""
    source, count = None, 0
    for stack in stacks:
        if stack.is_empty:
            continue
        if stack.id == source_id:
            if source is not None:
                return None
            source = stack
        elif stack.id == material_id:
            count += 1
        else:
            return None
    return (source, count) if source is not None and count else None


def _book_copies(stacks: list[ItemStack]) -> ItemStack | None:
    """BookCloningRecipe.assemble (1.20.5+): the written book, as many as the writable books, its
    content a copy a generation later (WrittenBookContent.tryCraftCopy); a book without content, or
    already a copy of a copy, makes the empty stack (the recipe matched, nothing is crafted)."""
    found = _cloned(stacks, WRITTEN_BOOK, "minecraft:writable_book")
    if found is None:
        return None
    source, count = found
    content = source.component("minecraft:written_book_content")
    generation = content.get("generation") if isinstance(content, Compound) else None
    generation = int(numeric_value(generation)) if is_numeric(generation) else 0
    if not isinstance(content, Compound) or generation >= 2:
        return items.EMPTY.copy()
    made = source.copy()
    made.count = count
    copied = Compound(content)
    copied["generation"] = Int(generation + 1)
    items.set_component(made, "minecraft:written_book_content", copied)
    return made


FIREWORK_ROCKET, TIPPED_ARROW = "minecraft:crafting_special_firework_rocket", "minecraft:crafting_special_tippedarrow"


def _rocket(stacks: list[ItemStack]) -> ItemStack | None:
    """FireworkRocketRecipe (1.20.5+): one paper, 1 - 3 gunpowder and any firework stars, nothing
    else; three rockets flying as long as the gunpowder, with the stars' explosions in order."""
    papers = sum(s.id == "minecraft:paper" for s in stacks)
    powder = sum(s.id == "minecraft:gunpowder" for s in stacks)
    others = [s for s in stacks if not s.is_empty and s.id not in ("minecraft:paper", "minecraft:gunpowder")]
    if papers != 1 or not 1 <= powder <= 3 or any(s.id != "minecraft:firework_star" for s in others):
        return None
    explosions = [s.component("minecraft:firework_explosion") for s in others]
    fireworks = Compound(flight_duration=Byte(powder))
    if any(e is not None for e in explosions):
        fireworks["explosions"] = List(e for e in explosions if e is not None)
    made = ItemStack("minecraft:firework_rocket", 3)
    items.set_component(made, "minecraft:fireworks", fireworks)
    return made


def _tipped_arrows(width: int, height: int, stacks: list[ItemStack]) -> ItemStack | None:
    """TippedArrowRecipe (1.20.5+): a full 3 x 3 grid of arrows round a lingering potion; eight
    tipped arrows with its potion contents."""
    if (width, height) != (3, 3) or stacks[4].id != "minecraft:lingering_potion" or any(
            s.id != "minecraft:arrow" for i, s in enumerate(stacks) if i != 4):
        return None
    made = ItemStack("minecraft:tipped_arrow", 8)
    contents = stacks[4].component("minecraft:potion_contents")
    if contents is not None:
        items.set_component(made, "minecraft:potion_contents", contents)
    return made


SHULKER_COLORING, SHULKER_COLORING_UNTIL = "minecraft:crafting_special_shulkerboxcoloring", (1, 21, 2)
_DYES = {f"minecraft:{colour}_dye": colour for colour in COLOURS}


def _coloured_box(stacks: list[ItemStack]) -> ItemStack | None:
    """ShulkerBoxColoring (1.20.5 - 1.21.1): one shulker box and one dye, nothing else; the box of
    the dye's colour with the box's components (ItemStack.transmuteCopy)."""
    present = [s for s in stacks if not s.is_empty]
    boxes = [s for s in present if s.id in SHULKER_BOXES]
    dyes = [s for s in present if s.id in _DYES]
    if len(boxes) != 1 or len(dyes) != 1 or len(present) != 2:
        return None
    return _transmute_copy(boxes[0], f"minecraft:{_DYES[dyes[0].id]}_shulker_box", 1)


def _remainders(kind: str, stacks: list[ItemStack]) -> list[ItemStack]:
    """CraftingRecipe.getRemainingItems: each stack's crafting remainder; BookCloningRecipe's keeps
    the (first) written book as well."""
    left = [ItemStack(REMAINDERS[s.id]) if s.id in REMAINDERS else items.EMPTY.copy() for s in stacks]
    if kind == BOOK_CLONING:
        first = next(i for i, s in enumerate(stacks) if s.id == WRITTEN_BOOK)
        left[first] = stacks[first].copy()
        left[first].count = 1
    return left


def _result(kind: str, body, width: int, height: int, stacks: list[ItemStack], resources, version):
    """The recipe's result for these stacks, None when it does not match; :data:`_UNMATCHED` for a
    recipe the emulator does not match."""
    if body is not None and kind == SHAPED:
        return result_stack(body["result"], version) if _shaped_matches(body, width, height, stacks, resources) else None
    if body is not None and kind == SHAPELESS:
        return result_stack(body["result"], version) if _shapeless_matches(body, stacks, resources) else None
    if body is not None and kind == TRANSMUTE and TRANSMUTE_SINCE <= tuple(version):
        if tuple(version) >= TRANSMUTE_REWRITTEN:
            return _transmuted_since_1_21_5(body, stacks, resources)
        return _transmuted(body, stacks, resources)
    if kind == BOOK_CLONING and items.COMPONENTS_VERSION <= tuple(version) < SPECIAL_UNTIL:
        return _book_copies(stacks)
    if kind == FIREWORK_ROCKET and items.COMPONENTS_VERSION <= tuple(version) < SPECIAL_UNTIL:
        return _rocket(stacks)
    if kind == TIPPED_ARROW and items.COMPONENTS_VERSION <= tuple(version) < SPECIAL_UNTIL:
        return _tipped_arrows(width, height, stacks)
    if kind == SHULKER_COLORING and items.COMPONENTS_VERSION <= tuple(version) < SHULKER_COLORING_UNTIL:
        return _coloured_box(stacks)
    if kind == MAP_CLONING and tuple(version) < SPECIAL_UNTIL:  # MapCloningRecipe.assemble: the map, one more
        found = _cloned(stacks, "minecraft:filled_map", "minecraft:map")
        if found is None:
            return None
        made = found[0].copy()
        made.count = found[1] + 1
        return made
    return _UNMATCHED if kind.startswith(UNMATCHED_PREFIXES) else None


_UNMATCHED = object()


def craft(resources, grid: list[ItemStack], version) -> Crafted | None:
    """RecipeManager.getRecipeFor(CRAFTING): the first recipe in the game's order
    (:func:`recipe_order`) that matches. A recipe the emulator does not match that could match
    before it, several pack recipes matching before 1.21.2 without the game's recipes (their order
    then depends on how many the game has), and no match without the game's recipes, are not
    modelled."""
    width, height, stacks = trimmed(grid)
    if not stacks:
        return None
    matched = []
    for recipe_id in recipe_order(resources.recipes, version):
        kind, body = resources.recipes[recipe_id], resources.recipe_bodies.get(recipe_id)
        found = _result(kind, body, width, height, stacks, resources, version)
        if found is _UNMATCHED:
            if _may_match(kind, body, stacks, resources):
                raise Unmodelled(f"crafting: {recipe_id} ({kind}) may match, which the emulator does not model")
            continue
        if found is not None:
            matched.append((recipe_id, found))
            if resources.vanilla_data or tuple(version) >= SORTED_RECIPES:
                break
    if len(matched) > 1:
        raise Unmodelled(f"crafting: {matched[0][0]} and {matched[1][0]} both match; before 1.21.2 the game "
                         "tries them in its recipe map's order, which depends on its own recipes (pass --game-jar)")
    if matched:
        recipe_id, result = matched[0]
        return Crafted(recipe_id, result, _remainders(resources.recipes[recipe_id], stacks))
    if not resources.vanilla_data:
        raise Unmodelled("crafting with no pack recipe matching: the game's own recipes are not known without "
                         "the game's data (pass --game-jar)")
    return None
