"""Brewing stands brewing: BrewingStandBlockEntity.serverTick with the game's potion mixes.

- ``tick(state, dimension, blocks, pos, nbt)``: out of fuel with a blaze powder in slot 4, the stand
  takes it (``Fuel`` 20). Brewing (``BrewTime`` > 0) counts down; at 0, if the ingredient (slot 3)
  still brews with a bottle, each bottle (slots 0 - 2) becomes its mix and one ingredient is used
  (a dragon's breath leaves its glass bottle when it was the last); while counting, another
  ingredient or nothing left to brew stops it (``BrewTime`` 0). Not brewing, an ingredient that
  brews with a bottle and fuel start it: one fuel used, ``BrewTime`` 400. The ``has_bottle_0..2``
  states follow slots 0 - 2.
- ``idle(state, dimension, blocks, pos, nbt) -> bool``: nothing would change.
- ``is_ingredient(stack)``, ``slots_for(face)``, ``can_place(slots, index, stack)``,
  ``can_take(index, stack)``: what a hopper may put in and take out (BrewingStandBlockEntity:
  from above the ingredient, from a side the bottles and the fuel, from below the bottles and the
  ingredient; slot 3 gives up only a glass bottle).

The mixes (PotionBrewing.addVanillaMixes) are 1.21's: a potion, splash or lingering potion with a
potion (``potion_contents``, or its id alone) mixes by potion (the new stack keeps the item and
only the new potion: PotionContents.createItemStack); a potion with gunpowder becomes a splash potion
and a splash potion with dragon's breath a lingering one (keeping the potion). The wind charged,
oozing, infested and weaving potions brew from 1.21. Not modelled (reported): potions in the NBT
form before 1.20.5, and a dragon's breath's bottle dropped beside the stand when more than one was
in the slot (Containers.dropItemStack's random spread).

The ingredient being brewed is not saved (BrewingStandBlockEntity.ingredient): a stand whose
``BrewTime`` was written by a command stops at its next tick, as one loaded from disk does.

Sources (decompiled 1.21): world/level/block/entity/BrewingStandBlockEntity.java (serverTick,
isBrewable, doBrew, getPotionBits, canPlaceItem, getSlotsForFace, canTakeItemThroughFace,
loadAdditional/saveAdditional: BrewTime short, Fuel byte), world/item/alchemy/PotionBrewing.java
(addVanillaMixes, isIngredient, hasMix, mix, Builder.addStartMix).
"""
from __future__ import annotations

from emulator.world import inventories
from emulator.world.errors import Unmodelled
from emulator.world.items import COMPONENTS_VERSION, EMPTY, ItemStack
from emulator.world.nbt_ops import int_at
from mcfunction_parser.nbt import Byte, Compound, Short, String

BREW_TIME, FUEL_USES = 400, 20
BLAZE_POWDER = "minecraft:blaze_powder"
CONTAINERS = ("minecraft:potion", "minecraft:splash_potion", "minecraft:lingering_potion")
BOTTLES = CONTAINERS + ("minecraft:glass_bottle",)
_CONTAINER_MIXES = (("minecraft:potion", "minecraft:gunpowder", "minecraft:splash_potion"),
                    ("minecraft:splash_potion", "minecraft:dragon_breath", "minecraft:lingering_potion"))
TRIAL_POTIONS_VERSION = (1, 21)
# PotionBrewing.addVanillaMixes in order: (from, ingredient, to), or ("start", ingredient, to) for
# addStartMix (water -> mundane, awkward -> the potion)
_MIXES = (
    ("water", "glowstone_dust", "thick"), ("water", "redstone", "mundane"), ("water", "nether_wart", "awkward"),
    ("start", "breeze_rod", "wind_charged"), ("start", "slime_block", "oozing"), ("start", "stone", "infested"),
    ("start", "cobweb", "weaving"),
    ("awkward", "golden_carrot", "night_vision"), ("night_vision", "redstone", "long_night_vision"),
    ("night_vision", "fermented_spider_eye", "invisibility"),
    ("long_night_vision", "fermented_spider_eye", "long_invisibility"), ("invisibility", "redstone", "long_invisibility"),
    ("start", "magma_cream", "fire_resistance"), ("fire_resistance", "redstone", "long_fire_resistance"),
    ("start", "rabbit_foot", "leaping"), ("leaping", "redstone", "long_leaping"),
    ("leaping", "glowstone_dust", "strong_leaping"), ("leaping", "fermented_spider_eye", "slowness"),
    ("long_leaping", "fermented_spider_eye", "long_slowness"), ("slowness", "redstone", "long_slowness"),
    ("slowness", "glowstone_dust", "strong_slowness"), ("awkward", "turtle_helmet", "turtle_master"),
    ("turtle_master", "redstone", "long_turtle_master"), ("turtle_master", "glowstone_dust", "strong_turtle_master"),
    ("swiftness", "fermented_spider_eye", "slowness"), ("long_swiftness", "fermented_spider_eye", "long_slowness"),
    ("start", "sugar", "swiftness"), ("swiftness", "redstone", "long_swiftness"),
    ("swiftness", "glowstone_dust", "strong_swiftness"), ("awkward", "pufferfish", "water_breathing"),
    ("water_breathing", "redstone", "long_water_breathing"), ("start", "glistering_melon_slice", "healing"),
    ("healing", "glowstone_dust", "strong_healing"), ("healing", "fermented_spider_eye", "harming"),
    ("strong_healing", "fermented_spider_eye", "strong_harming"), ("harming", "glowstone_dust", "strong_harming"),
    ("poison", "fermented_spider_eye", "harming"), ("long_poison", "fermented_spider_eye", "harming"),
    ("strong_poison", "fermented_spider_eye", "strong_harming"), ("start", "spider_eye", "poison"),
    ("poison", "redstone", "long_poison"), ("poison", "glowstone_dust", "strong_poison"),
    ("start", "ghast_tear", "regeneration"), ("regeneration", "redstone", "long_regeneration"),
    ("regeneration", "glowstone_dust", "strong_regeneration"), ("start", "blaze_powder", "strength"),
    ("strength", "redstone", "long_strength"), ("strength", "glowstone_dust", "strong_strength"),
    ("water", "fermented_spider_eye", "weakness"), ("weakness", "redstone", "long_weakness"),
    ("awkward", "phantom_membrane", "slow_falling"), ("slow_falling", "redstone", "long_slow_falling"),
)
_TRIAL_POTIONS = frozenset({"wind_charged", "oozing", "infested", "weaving"})
_SLOTS = {"up": (3,), "down": (0, 1, 2, 3)}
_SIDE_SLOTS = (0, 1, 2, 4)


def _potion_mixes(version) -> list[tuple[str, str, str]]:
    """The potion mixes of the release, start mixes expanded (Builder.addStartMix)."""
    found = []
    for source, ingredient, to in _MIXES:
        if to in _TRIAL_POTIONS and tuple(version) < TRIAL_POTIONS_VERSION:
            continue
        pairs = (("water", "mundane"), ("awkward", to)) if source == "start" else ((source, to),)
        found += [(f"minecraft:{a}", f"minecraft:{ingredient}", f"minecraft:{b}") for a, b in pairs]
    return found


def potion_of(stack: ItemStack, version) -> str | None:
    """PotionContents.potion() of the stack (the component, or the potion's id alone)."""
    if tuple(version) < COMPONENTS_VERSION:
        raise Unmodelled("brewing potions in the NBT form before 1.20.5")
    contents = stack.component("minecraft:potion_contents")
    potion = contents.get("potion") if isinstance(contents, Compound) else contents
    if not isinstance(potion, str):
        return None
    potion = str(potion)
    return potion if ":" in potion else f"minecraft:{potion}"


def is_ingredient(stack: ItemStack, version) -> bool:
    """PotionBrewing.isIngredient."""
    return any(stack.id == i for _, i, _ in _CONTAINER_MIXES) or any(
        stack.id == i for _, i, _ in _potion_mixes(version))


def _has_mix(bottle: ItemStack, ingredient: ItemStack, version) -> bool:
    """PotionBrewing.hasMix: a potion container with a container mix or a potion mix."""
    if bottle.id not in CONTAINERS:
        return False
    if any(bottle.id == a and ingredient.id == i for a, i, _ in _CONTAINER_MIXES):
        return True
    potion = potion_of(bottle, version)
    return potion is not None and any(potion == a and ingredient.id == i for a, i, _ in _potion_mixes(version))


def _mixed(ingredient: ItemStack, bottle: ItemStack, version) -> ItemStack:
    """PotionBrewing.mix: the container mix (the new item, the same potion), else the potion mix
    (the same item, the new potion), else the bottle as it was."""
    if bottle.is_empty:
        return bottle
    potion = potion_of(bottle, version)
    if potion is None:
        return bottle
    for source, with_item, to in _CONTAINER_MIXES:
        if bottle.id == source and ingredient.id == with_item:
            return _potion_stack(to, potion)
    for source, with_item, to in _potion_mixes(version):
        if potion == source and ingredient.id == with_item:
            return _potion_stack(bottle.id, to)
    return bottle


def _potion_stack(item_id: str, potion: str) -> ItemStack:
    """PotionContents.createItemStack: one of the item with only the potion in its contents."""
    return ItemStack(item_id, 1, Compound({"minecraft:potion_contents": Compound(potion=String(potion))}))


def _brewable(slots: list[ItemStack], version) -> bool:
    """BrewingStandBlockEntity.isBrewable."""
    ingredient = slots[3]
    if ingredient.is_empty or not is_ingredient(ingredient, version):
        return False
    return any(not s.is_empty and _has_mix(s, ingredient, version) for s in slots[:3])


# ---------------------------------------------------------------------- a hopper's view
def slots_for(face: str) -> tuple[int, ...]:
    return _SLOTS.get(face, _SIDE_SLOTS)


def can_place(current: list[ItemStack], index: int, stack: ItemStack, version) -> bool:
    """canPlaceItem: the ingredient slot an ingredient, the fuel slot blaze powder, a bottle slot
    a potion or glass bottle while empty."""
    if index == 3:
        return is_ingredient(stack, version)
    if index == 4:
        return stack.id == BLAZE_POWDER
    return stack.id in BOTTLES and current[index].is_empty


def can_take(index: int, stack: ItemStack) -> bool:
    return stack.id == "minecraft:glass_bottle" if index == 3 else True


# ---------------------------------------------------------------------- the tick

def _write(box, slots: list[ItemStack], index: int, stack: ItemStack) -> None:
    slots[index] = stack
    box.slot(index).set(stack if not stack.is_empty else EMPTY.copy())


def _brew(box, slots: list[ItemStack], version) -> None:
    """doBrew: each bottle mixed, one ingredient used; the last dragon's breath leaves its bottle."""
    ingredient = slots[3].copy()
    if ingredient.id == "minecraft:dragon_breath" and ingredient.count > 1:
        raise Unmodelled("a brewing stand dropping the glass bottle of a dragon's breath beside it")
    for i in range(3):
        mixed = _mixed(ingredient, slots[i], version)
        if mixed is not slots[i]:
            _write(box, slots, i, mixed)
    ingredient.count -= 1
    if ingredient.id == "minecraft:dragon_breath":
        ingredient = ItemStack("minecraft:glass_bottle", 1)
    _write(box, slots, 3, ingredient if ingredient.count > 0 else EMPTY.copy())


def _show_bottles(blocks, pos, slots: list[ItemStack]) -> None:
    block = blocks.get(pos)
    bottles = {f"has_bottle_{i}": "false" if slots[i].is_empty else "true" for i in range(3)}
    properties = dict(block.properties)
    if any(properties.get(k) not in (None, v) for k, v in bottles.items()):
        blocks.set_state(pos, type(block)(block.id, tuple(sorted({**properties, **bottles}.items()))))


def tick(state, dimension, blocks, pos, nbt) -> None:
    """BrewingStandBlockEntity.serverTick."""
    version = state.version
    box = inventories.Container(nbt, 5, version)
    slots = [box.slot(i).get() for i in range(5)]
    fuel, brew_time = int_at(nbt, "Fuel"), int_at(nbt, "BrewTime")
    if fuel <= 0 and slots[4].id == BLAZE_POWDER:
        fuel = FUEL_USES
        powder = slots[4].copy()
        powder.count -= 1
        _write(box, slots, 4, powder)
    key = (dimension, pos)
    held = state.brewing.get(key)
    brewing_item = held[1] if held is not None and held[0] is nbt else None
    if brew_time > 0 or (fuel > 0 and not slots[3].is_empty):
        brewable = _brewable(slots, version)
        if brew_time > 0:
            brew_time -= 1
            if brew_time == 0 and brewable:
                _brew(box, slots, version)
            elif not brewable or slots[3].id != brewing_item:
                brew_time = 0
        elif brewable:
            fuel -= 1
            brew_time = BREW_TIME
            state.brewing[key] = (nbt, slots[3].id)
    nbt["Fuel"], nbt["BrewTime"] = Byte(fuel), Short(brew_time)
    _show_bottles(blocks, pos, slots)


def idle(state, dimension, blocks, pos, nbt) -> bool:
    box = inventories.Container(nbt, 5, state.version)
    slots = [box.slot(i).get() for i in range(5)]
    fuel = int_at(nbt, "Fuel")
    if int_at(nbt, "BrewTime") > 0 or (fuel <= 0 and slots[4].id == BLAZE_POWDER):
        return False
    if fuel > 0 and _brewable(slots, state.version):
        return False
    properties = dict(blocks.get(pos).properties)
    return all(properties.get(f"has_bottle_{i}") in (None, "false" if slots[i].is_empty else "true") for i in range(3))
