"""Furnaces, smokers and blast furnaces burning fuel and cooking what is in them.

- ``tick(state, blocks, pos, nbt)``: AbstractFurnaceBlockEntity.serverTick: a lit furnace burns
  one tick of its fuel; with an input it can cook (a recipe of its type whose result fits the
  output slot) an unlit one takes a fuel (its burn time; what a bucket of lava leaves behind
  stays), a lit one advances the cooking; when the progress reaches the total, one input becomes
  the recipe's result, the recipe is counted in ``RecipesUsed`` (the experience a player gets when
  taking the output is worked out from it then) and the total is read again. Unlit, the progress
  falls back by 2. The block's ``lit`` state follows.
- ``idle(state, block_id, nbt) -> bool``: nothing would change (unlit, no progress, and no fuel
  taken: fuel or input missing, or no room for what the input cooks into).
- ``input_set(resources, block_id, nbt, before, after, version)``: AbstractFurnaceBlockEntity.
  setItem of the input slot (item commands, hoppers): another item restarts the progress and
  reads the total cooking time of the new input's recipe (200 without one; kept as it was when
  the recipe is not known, as the tick then reports). Data commands do not (the game loads the
  NBT as written).
- ``is_fuel(stack, resources)`` / ``burn_time(block_id, stack, resources)``: the fuel map
  (AbstractFurnaceBlockEntity.getFuel: items and item tags; smokers and blast furnaces burn it
  twice as fast).

Recipes: the pack's own ``smelting``/``smoking``/``blasting`` recipes, and the game's when its data
is loaded (``--game-jar``), tried in RecipeManager's order (:func:`emulator.world.crafting.
recipe_order`); the ingredient is matched by item only, the result is the recipe's stack (before
1.20.5 an item id), ``cookingtime`` defaults to 200 for smelting and 100 for smoking and blasting.
An input no pack recipe cooks, without the game's recipes, is not modelled (reported), as is a
fuel that only a vanilla item tag would make one (logs, planks, wool ...) without the game's tags.

Saved keys: ``BurnTime``, ``CookTime``, ``CookTimeTotal`` (shorts), and from 1.21.4
``lit_time_remaining``, ``cooking_time_spent``, ``cooking_total_time``, ``lit_total_time``.
The fuel map is the one of 1.21.1; from 1.21.2 the game reads it from FuelValues.vanillaBurnTimes,
whose entries are taken to be the same here. The game tries the recipe a furnace used last before
the others (RecipeManager.CachedCheck, not saved); here the first in order always wins, which
differs only when two recipes of the type take the same input.

Sources (decompiled 1.21): world/level/block/entity/AbstractFurnaceBlockEntity.java (getFuel,
serverTick, canBurn, burn, getBurnDuration, getTotalCookTime, isFuel, setItem, setRecipeUsed,
saveAdditional), SmokerBlockEntity / BlastFurnaceBlockEntity.getBurnDuration (half),
world/item/crafting/AbstractCookingRecipe, CookingBookCategory defaults (SimpleCookingSerializer).
"""
from __future__ import annotations

from emulator.world import crafting
from emulator.world.inventories import FURNACES, Container
from emulator.world.errors import Unmodelled
from emulator.world.items import EMPTY, ItemStack
from emulator.world.loot_context import namespaced as _id
from emulator.world.nbt_ops import int_at
from mcfunction_parser.nbt import Compound, Int, Short

RECIPE_TYPES = {"minecraft:furnace": "minecraft:smelting", "minecraft:smoker": "minecraft:smoking",
                "minecraft:blast_furnace": "minecraft:blasting"}
_DEFAULT_COOK_TIME = {"minecraft:smelting": 200, "minecraft:smoking": 100, "minecraft:blasting": 100}
NO_RECIPE_COOK_TIME = 200  # getTotalCookTime without a recipe
KEYS_VERSION = (1, 21, 4)  # the keys renamed (BlockEntityFurnaceBurnTimeFix)
COMPONENTS_VERSION = (1, 20, 5)  # a cooking recipe's result: an item stack, an item id before

# AbstractFurnaceBlockEntity.getFuel (1.21), in its order; "#" marks an item tag
_FUEL = (
    ("lava_bucket", 20000), ("coal_block", 16000), ("blaze_rod", 2400), ("coal", 1600), ("charcoal", 1600),
    ("#logs", 300), ("#bamboo_blocks", 300), ("#planks", 300), ("bamboo_mosaic", 300), ("#wooden_stairs", 300),
    ("bamboo_mosaic_stairs", 300), ("#wooden_slabs", 150), ("bamboo_mosaic_slab", 150), ("#wooden_trapdoors", 300),
    ("#wooden_pressure_plates", 300), ("#wooden_fences", 300), ("#fence_gates", 300), ("note_block", 300),
    ("bookshelf", 300), ("chiseled_bookshelf", 300), ("lectern", 300), ("jukebox", 300), ("chest", 300),
    ("trapped_chest", 300), ("crafting_table", 300), ("daylight_detector", 300), ("#banners", 300), ("bow", 300),
    ("fishing_rod", 300), ("ladder", 300), ("#signs", 200), ("#hanging_signs", 800), ("wooden_shovel", 200),
    ("wooden_sword", 200), ("wooden_hoe", 200), ("wooden_axe", 200), ("wooden_pickaxe", 200),
    ("#wooden_doors", 200), ("#boats", 1200), ("#wool", 100), ("#wooden_buttons", 100), ("stick", 100),
    ("#saplings", 100), ("bowl", 100), ("#wool_carpets", 67), ("dried_kelp_block", 4001), ("crossbow", 300),
    ("bamboo", 50), ("dead_bush", 100), ("scaffolding", 50), ("loom", 300), ("barrel", 300),
    ("cartography_table", 300), ("fletching_table", 300), ("smithing_table", 300), ("composter", 300),
    ("azalea", 100), ("flowering_azalea", 100), ("mangrove_roots", 300),
)
_FUEL_ITEMS = {f"minecraft:{name}": time for name, time in _FUEL if not name.startswith("#")}
_FUEL_TAGS = tuple((f"minecraft:{name[1:]}", time) for name, time in _FUEL if name.startswith("#"))
# Item.getCraftingRemainingItem of the fuels: the last fuel burnt leaves it in the fuel slot
_REMAINDERS = {"minecraft:lava_bucket": "minecraft:bucket"}



def keys(version) -> tuple[str, str, str, str | None]:
    """(lit time, cooking progress, cooking total, lit total or None when not saved)."""
    if tuple(version) >= KEYS_VERSION:
        return "lit_time_remaining", "cooking_time_spent", "cooking_total_time", "lit_total_time"
    return "BurnTime", "CookTime", "CookTimeTotal", None


def _fuel_time(stack: ItemStack, resources) -> int:
    """getFuel().getOrDefault(item, 0): the items named, else the item tags in the map's order
    (a later entry overrides an earlier one: Map.put). The tags are read from the game's data and
    the packs; one the emulator does not know makes the answer not modelled."""
    if stack.is_empty:
        return 0
    if stack.id in _FUEL_ITEMS:
        return _FUEL_ITEMS[stack.id]
    found = 0
    for tag, time in _FUEL_TAGS:
        if resources.in_tag("item", tag, stack.id):
            found = time
    return found


def is_fuel(stack: ItemStack, resources) -> bool:
    """AbstractFurnaceBlockEntity.isFuel."""
    return _fuel_time(stack, resources) > 0


def burn_time(block_id: str, stack: ItemStack, resources) -> int:
    """getBurnDuration: the fuel's time; half (integer division) in a smoker or a blast furnace."""
    time = _fuel_time(stack, resources)
    return time if block_id == "minecraft:furnace" else time // 2


# ---------------------------------------------------------------------- recipes
def recipe_result(recipe: dict, version) -> ItemStack:
    """A cooking recipe's result stack (an id before 1.20.5, a stack from then)."""
    result = recipe.get("result")
    if isinstance(result, str):
        return ItemStack(_id(result), 1)
    return crafting.result_stack(result or {}, version)


# the recipes of each cooking type in the game's order, for the world's resources last asked
_ORDERS: list = [None, {}]


def _ordered(resources, kind: str, version: tuple) -> list[str]:
    if _ORDERS[0] is not resources:
        _ORDERS[:] = [resources, {}]
    found = _ORDERS[1].get((kind, version))
    if found is None:
        ids = [rid for rid, body in resources.recipe_bodies.items() if isinstance(body, dict)
               and _id(str(body.get("type", ""))) == kind]
        found = _ORDERS[1][(kind, version)] = crafting.recipe_order(ids, version)
    return found


def recipe_for(block_id: str, stack: ItemStack, resources, version) -> tuple[str, dict] | None:
    """RecipeManager.getRecipeFor(the furnace's type, the input): (id, JSON) of the first recipe
    whose ingredient takes the item; None when none does. The game's own are not modelled without
    its data."""
    if stack.is_empty:
        return None
    kind = RECIPE_TYPES[block_id]
    for rid in _ordered(resources, kind, tuple(version)):
        body = resources.recipe_bodies[rid]
        if crafting.ingredient_test(body.get("ingredient"), stack, resources):
            return rid, body
    if not resources.vanilla_data:
        raise Unmodelled(f"{block_id} cooking {stack.id}: the game's own {kind.removeprefix('minecraft:')} recipes "
                         "are not known without the game's data (pass --game-jar)")
    return None


def cook_time(block_id: str, recipe: dict | None) -> int:
    """getTotalCookTime: the recipe's ``cookingtime``, 200 without a recipe."""
    if recipe is None:
        return NO_RECIPE_COOK_TIME
    time = recipe.get("cookingtime")
    return int(time) if isinstance(time, (int, float)) else _DEFAULT_COOK_TIME[RECIPE_TYPES[block_id]]


def input_set(resources, block_id: str, nbt: Compound, before: ItemStack, after: ItemStack, version) -> None:
    """setItem(0, after): unless ``after`` is the same item and components as ``before``, the total
    cooking time is read again and the progress restarts."""
    if not after.is_empty and before.same_item_same_components(after):
        return
    _, progress, total, _ = keys(version)
    nbt[progress] = Short(0)
    try:
        found = recipe_for(block_id, after, resources, version)
    except Unmodelled:
        return  # the total only matters once it cooks, where the tick reports the recipe unknown
    nbt[total] = Short(cook_time(block_id, found[1] if found else None))


# ---------------------------------------------------------------------- the tick
class _Slots:
    """The furnace's three stacks, read once and written back when changed."""

    def __init__(self, nbt: Compound, version) -> None:
        self.container = Container(nbt, 3, version)
        self.stacks = [self.container.slot(i).get() for i in range(3)]

    def write(self, index: int, stack: ItemStack) -> None:
        self.stacks[index] = stack
        self.container.slot(index).set(stack if stack.count > 0 else EMPTY.copy())


def _can_burn(result: ItemStack | None, slots: _Slots) -> bool:
    """canBurn: an input, a recipe with a result, and room for it in the output (the same item and
    components below 64 and the stack's max)."""
    if slots.stacks[0].is_empty or result is None or result.is_empty:
        return False
    out = slots.stacks[2]
    if out.is_empty:
        return True
    if not out.same_item_same_components(result):
        return False
    return (out.count < 64 and out.count < out.max_stack_size) or out.count < result.max_stack_size


def idle(state, block_id: str, nbt) -> bool:
    """Unlit with no progress, and no fuel to take: one slot empty, or nothing the input cooks into
    that fits the output."""
    lit, progress, _, _ = keys(state.version)
    if int_at(nbt, lit) > 0 or int_at(nbt, progress) > 0:
        return False
    slots = _Slots(nbt, state.version)
    if slots.stacks[0].is_empty or slots.stacks[1].is_empty:
        return True
    found = recipe_for(block_id, slots.stacks[0], state.resources, state.version)
    return not _can_burn(recipe_result(found[1], state.version) if found else None, slots)


def _set_lit(blocks, pos, lit: bool) -> None:
    block = blocks.get(pos)
    properties = dict(block.properties)
    if properties.get("lit") not in (None, "true" if lit else "false"):
        properties["lit"] = "true" if lit else "false"
        blocks.set_state(pos, type(block)(block.id, tuple(sorted(properties.items()))))


def tick(state, blocks, pos, nbt) -> None:
    """AbstractFurnaceBlockEntity.serverTick."""
    version, resources = state.version, state.resources
    block_id = blocks.get(pos).id
    lit_key, progress_key, total_key, lit_total_key = keys(version)
    lit, progress, total = int_at(nbt, lit_key), int_at(nbt, progress_key), int_at(nbt, total_key)
    was_lit = lit > 0
    if was_lit:
        lit -= 1
    slots = _Slots(nbt, version)
    fuel, cooking = slots.stacks[1], slots.stacks[0]
    if lit > 0 or (not fuel.is_empty and not cooking.is_empty):
        found = recipe_for(block_id, cooking, resources, version) if not cooking.is_empty else None
        result = recipe_result(found[1], version) if found else None
        if lit <= 0 and _can_burn(result, slots):
            lit = burn_time(block_id, fuel, resources)
            if lit_total_key is not None:
                nbt[lit_total_key] = Short(lit)
            if lit > 0 and not fuel.is_empty:
                fuel = fuel.copy()
                fuel.count -= 1
                remainder = _REMAINDERS.get(fuel.id)
                slots.write(1, fuel if fuel.count > 0 else ItemStack(remainder, 1) if remainder else EMPTY.copy())
        if lit > 0 and _can_burn(result, slots):
            progress += 1
            if progress == total:
                progress = 0
                total = cook_time(block_id, found[1])
                _burn(found, result, slots, nbt)
        else:
            progress = 0
    elif progress > 0:
        progress = min(max(progress - 2, 0), total)
    nbt[lit_key], nbt[progress_key], nbt[total_key] = Short(lit), Short(progress), Short(total)
    if was_lit != (lit > 0):
        _set_lit(blocks, pos, lit > 0)


def _burn(found: tuple[str, dict], result: ItemStack, slots: _Slots, nbt: Compound) -> None:
    """burn: the result into the output, a wet sponge fills a bucket in the fuel slot, one input
    used; setRecipeUsed counts the recipe in ``RecipesUsed``."""
    out = slots.stacks[2]
    if out.is_empty:
        slots.write(2, result.copy())
    elif out.same_item_same_components(result):
        out.count += 1
        slots.write(2, out)
    cooking = slots.stacks[0]
    if cooking.id == "minecraft:wet_sponge" and slots.stacks[1].id == "minecraft:bucket":
        slots.write(1, ItemStack("minecraft:water_bucket", 1))
    cooking = cooking.copy()
    cooking.count -= 1
    slots.write(0, cooking)
    used = nbt.get("RecipesUsed")
    if not isinstance(used, Compound):
        used = nbt["RecipesUsed"] = Compound()
    used[found[0]] = Int(int_at(used, found[0]) + 1)

