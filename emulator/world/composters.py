"""Composters filled and emptied by hoppers: what ComposterBlock's containers do.

- ``chance(item_id, version) -> float | None``: COMPOSTABLES (the chance an item raises the level),
  None for an item that does not compost. The table is 1.21's; from 1.21.4 an item not in it (the
  pale garden's plants, leaf litter ...) is not modelled rather than taken as not compostable.
- ``add_item(state, dimension, blocks, pos, item_id)``: ComposterBlock.addItem: an empty composter
  always rises to level 1, another one with the item's chance (the level's random; not the game's
  sequence of draws); reaching 7 it becomes ready (8) 20 ticks later (a scheduled block tick:
  ComposterBlock.tick).
- ``empty(blocks, pos)``: ComposterBlock.empty: back to level 0 (a hopper took the bone meal).

Sources (decompiled 1.21): world/level/block/ComposterBlock.java (bootStrap, addItem, tick,
empty, getContainer, InputContainer, OutputContainer, EmptyContainer).
"""
from __future__ import annotations

from emulator.world.errors import Unmodelled

COMPOSTER = "minecraft:composter"
READY, FULL = 8, 7
READY_DELAY = 20
TABLE_UNTIL = (1, 21, 3)  # 1.21.4 added compostables (pale oak leaves and sapling, pale moss, eyeblossoms)
_CHANCES = {
    0.3: "jungle_leaves oak_leaves spruce_leaves dark_oak_leaves acacia_leaves cherry_leaves birch_leaves "
         "azalea_leaves mangrove_leaves oak_sapling spruce_sapling birch_sapling jungle_sapling acacia_sapling "
         "cherry_sapling dark_oak_sapling mangrove_propagule beetroot_seeds dried_kelp short_grass kelp "
         "melon_seeds pumpkin_seeds seagrass sweet_berries glow_berries wheat_seeds moss_carpet pink_petals "
         "small_dripleaf hanging_roots mangrove_roots torchflower_seeds pitcher_pod",
    0.5: "dried_kelp_block tall_grass flowering_azalea_leaves cactus sugar_cane vine nether_sprouts weeping_vines "
         "twisting_vines melon_slice glow_lichen",
    0.65: "sea_pickle lily_pad pumpkin carved_pumpkin melon apple beetroot carrot cocoa_beans potato wheat "
          "brown_mushroom red_mushroom mushroom_stem crimson_fungus warped_fungus nether_wart crimson_roots "
          "warped_roots shroomlight dandelion poppy blue_orchid allium azure_bluet red_tulip orange_tulip "
          "white_tulip pink_tulip oxeye_daisy cornflower lily_of_the_valley wither_rose fern sunflower lilac "
          "rose_bush peony large_fern spore_blossom azalea moss_block big_dripleaf",
    0.85: "hay_block brown_mushroom_block red_mushroom_block nether_wart_block warped_wart_block flowering_azalea "
          "bread baked_potato cookie torchflower pitcher_plant",
    1.0: "cake pumpkin_pie",
}
COMPOSTABLES = {f"minecraft:{name}": odds for odds, names in _CHANCES.items() for name in names.split()}


def level(block) -> int:
    return int(dict(block.properties).get("level", "0"))


def chance(item_id: str, version) -> float | None:
    found = COMPOSTABLES.get(item_id)
    if found is None and tuple(version) > TABLE_UNTIL:
        raise Unmodelled(f"whether {item_id} composts in this release (the compostables known are 1.21's)")
    return found


def _set_level(blocks, pos, value: int) -> None:
    block = blocks.get(pos)
    properties = {**dict(block.properties), "level": str(value)}
    blocks.set_state(pos, type(block)(block.id, tuple(sorted(properties.items()))))


def _ripen(level_view, pos) -> None:
    """ComposterBlock.tick: a composter at level 7 becomes ready."""
    if level(level_view.blocks.get(pos)) == FULL:
        _set_level(level_view.blocks, pos, READY)


def add_item(state, dimension, blocks, pos, item_id: str) -> None:
    """ComposterBlock.addItem."""
    current, odds = level(blocks.get(pos)), chance(item_id, state.version) or 0.0
    if not ((current == 0 and odds > 0) or state.random.random() < odds):
        return
    _set_level(blocks, pos, current + 1)
    if current + 1 == FULL:
        view = state.level(dimension)
        view.block_ticks.schedule(pos, COMPOSTER, READY_DELAY, view.gametime, _ripen)


def empty(blocks, pos) -> None:
    _set_level(blocks, pos, 0)
