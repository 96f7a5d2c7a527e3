"""A player using an item on a cauldron (AbstractCauldronBlock.useItemOn -> CauldronInteraction),
with what a datapack observes: the cauldron's block and level, the item in hand, the statistics
``fill_cauldron`` / ``use_cauldron`` and ``minecraft.used:<item>``.

- ``use_item_on(state, player, hand, pos, block, stack) -> str``: ``"consume"`` when the cauldron
  took or gave something, ``"try_empty_hand"`` (PASS_TO_DEFAULT_BLOCK_INTERACTION) otherwise.

Modelled (CauldronInteraction.bootStrap, 1.20.5+): on any cauldron a water, lava or powder snow
bucket fills it (``water_cauldron[level=3]``, ``lava_cauldron``, ``powder_snow_cauldron[level=3]``)
and leaves an empty bucket (emptyBucket: ``fill_cauldron``); an empty bucket takes a full one
(water or powder snow at level 3, lava) back, leaving ``cauldron`` (fillBucket: ``use_cauldron``);
a water bottle pours into an empty cauldron (``water_cauldron[level=1]``) or one below level 3
(one level up), a glass bottle takes one level (the last leaves ``cauldron``): both
``use_cauldron``. The hand's item goes as ItemUtils.createFilledResult says (the new item replaces
the last one, else goes to the inventory or is dropped; a creative player keeps its item and gets
the new one if it has none). Not modelled (Unmodelled): washing dyed leather, banners and shulker
boxes in water (their components).

Sources (decompiled 1.21): core/cauldron/CauldronInteraction.java (bootStrap, addDefaultInteractions,
fillBucket, emptyBucket, FILL_WATER/LAVA/POWDER_SNOW, DYED_ITEM, BANNER, SHULKER_BOX),
world/level/block/AbstractCauldronBlock.java (useItemOn), LayeredCauldronBlock.java
(lowerFillLevel), world/item/ItemUtils.java (createFilledResult).
"""
from __future__ import annotations

from emulator.world import inventories, statistics
from emulator.world.blocks import BlockState
from emulator.world.errors import Unmodelled
from emulator.world.id_families import COLOURS
from emulator.world.items import ItemStack, set_component
from emulator.world.player_actions import filled_result, hand_slot
from mcfunction_parser.nbt import Compound, String

CAULDRON, WATER, LAVA, SNOW = ("minecraft:cauldron", "minecraft:water_cauldron", "minecraft:lava_cauldron",
                               "minecraft:powder_snow_cauldron")
CAULDRONS = frozenset((CAULDRON, WATER, LAVA, SNOW))
# what a full bucket puts in (emptyBucket) and what a full cauldron gives an empty bucket (fillBucket)
FILLS = {"minecraft:water_bucket": (WATER, {"level": "3"}), "minecraft:lava_bucket": (LAVA, {}),
         "minecraft:powder_snow_bucket": (SNOW, {"level": "3"})}
BUCKETS = {WATER: "minecraft:water_bucket", LAVA: "minecraft:lava_bucket", SNOW: "minecraft:powder_snow_bucket"}
# washed in a water cauldron (DYED_ITEM, BANNER, SHULKER_BOX)
_WASHED = frozenset("minecraft:" + n for n in (
    "leather_boots leather_leggings leather_chestplate leather_helmet leather_horse_armor wolf_armor").split()) | \
    frozenset(f"minecraft:{c}_{kind}" for c in COLOURS for kind in ("banner", "shulker_box"))


def _level(block) -> int:
    return int(dict(block.properties).get("level", "3"))


def is_water_bottle(stack) -> bool:
    """PotionContents.is(Potions.WATER): a potion whose ``potion_contents`` names water."""
    contents = stack.component("minecraft:potion_contents")
    potion = contents.get("potion") if isinstance(contents, Compound) else contents
    return potion is not None and str(potion).removeprefix("minecraft:") == "water"


def _hand_becomes(state, player, hand: str, stack, new_id: str, filled: ItemStack | None = None) -> None:
    access = inventories.entity_slot(player, hand_slot(hand), state.version)
    access.set(filled_result(state, player, stack, filled if filled is not None else ItemStack(new_id, 1)))


def _water_bottle() -> ItemStack:
    bottle = ItemStack("minecraft:potion", 1)
    set_component(bottle, "minecraft:potion_contents", Compound(potion=String("minecraft:water")))
    return bottle


def use_item_on(state, player, hand: str, pos, block, stack) -> str:
    """The cauldron's CauldronInteraction for the held item (see the module's doc)."""
    kind = block.id
    used = stack.id
    stat = None
    if used in FILLS:
        new_block, properties = FILLS[used]
        _hand_becomes(state, player, hand, stack, "minecraft:bucket")
        stat = "fill_cauldron"
    elif used == "minecraft:bucket" and kind in BUCKETS and (kind == LAVA or _level(block) == 3):
        _hand_becomes(state, player, hand, stack, BUCKETS[kind])
        new_block, properties, stat = CAULDRON, {}, "use_cauldron"
    elif used == "minecraft:potion" and kind in (CAULDRON, WATER) and is_water_bottle(stack) and \
            (kind == CAULDRON or _level(block) < 3):
        _hand_becomes(state, player, hand, stack, "minecraft:glass_bottle")
        new_block, properties = WATER, {"level": str(_level(block) + 1 if kind == WATER else 1)}
        stat = "use_cauldron"
    elif used == "minecraft:glass_bottle" and kind == WATER:
        _hand_becomes(state, player, hand, stack, "", _water_bottle())
        level = _level(block) - 1  # LayeredCauldronBlock.lowerFillLevel
        new_block, properties = (WATER, {"level": str(level)}) if level else (CAULDRON, {})
        stat = "use_cauldron"
    elif used in _WASHED and kind == WATER:
        raise Unmodelled(f"washing {used} in a water cauldron (CauldronInteraction: its components)")
    else:
        return "try_empty_hand"
    state.blocks.set_state(pos, BlockState.of(new_block, properties))
    statistics.award(state, player, statistics.stat_name("custom", stat))
    statistics.award(state, player, statistics.stat_name("used", used))
    return "consume"
