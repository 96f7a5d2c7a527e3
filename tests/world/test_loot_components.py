"""The item functions that write one component whole (:mod:`emulator.world.loot_components`), as
the game saves the component: SetBookCoverFunction, SetWritableBookPagesFunction,
SetFireworksFunction, SetFireworkExplosionFunction, SetBannerPatternFunction, DiscardItem, and
ListOperation's bounds (decompiled 1.21)."""
from __future__ import annotations

import random

from emulator.world import items, loot
from emulator.world.loot_context import LootContext
from emulator.world.resources import Resources
from emulator.world.state import WorldState
from mcfunction_parser.nbt import List, to_snbt

V121 = (1, 21, 4)


def modified(modifier, item_id: str, version=V121) -> items.ItemStack:
    ctx = LootContext(WorldState(version=version, resources=Resources()), random=random.Random(0))
    return loot.apply_modifier(modifier, items.ItemStack(item_id), ctx)


def component(stack: items.ItemStack, name: str) -> str:
    """The component as SNBT, its compounds' keys sorted (as the game's text visitor prints them)."""
    return to_snbt(_sorted(stack.component(f"minecraft:{name}")))


def _sorted(tag):
    if isinstance(tag, dict):
        return type(tag)((key, _sorted(tag[key])) for key in sorted(tag))
    if isinstance(tag, list) and type(tag) is List:
        return List(_sorted(value) for value in tag)
    return tag


def test_book_cover_starts_from_the_empty_book():
    # WrittenBookContent.EMPTY: title "", author "", generation 0, resolved; the codec leaves out
    # generation 0 and no pages; a title is Filterable ({raw})
    book = modified({"function": "set_book_cover", "author": "Steve"}, "minecraft:written_book")
    assert component(book, "written_book_content") == '{author:"Steve",resolved:1b,title:{raw:""}}'
    book = modified([{"function": "set_book_cover", "title": "T", "generation": 2},
                     {"function": "set_book_cover", "title": {"raw": "Raw", "filtered": "F"}}], "minecraft:written_book")
    assert component(book, "written_book_content") == \
        '{author:"",generation:2,resolved:1b,title:{filtered:"F",raw:"Raw"}}'


def test_writable_pages_by_list_operation():
    steps = [{"function": "set_writable_book_pages", "pages": ["a", "b"], "mode": "replace_all"},
             {"function": "set_writable_book_pages", "pages": ["x"], "mode": "insert", "offset": 1},
             {"function": "set_writable_book_pages", "pages": ["z"], "mode": "replace_section", "offset": 2}]
    book = modified(steps, "minecraft:writable_book")
    assert component(book, "writable_book_content") == '{pages:[{raw:"a"},{raw:"x"},{raw:"z"}]}'
    # an offset past the end leaves the pages (ListOperation: "offset is out of bounds", logged)
    book = modified(steps[:1] + [{"function": "set_writable_book_pages", "pages": ["q"], "mode": "insert",
                                  "offset": 5}], "minecraft:writable_book")
    assert component(book, "writable_book_content") == '{pages:[{raw:"a"},{raw:"b"}]}'


def test_fireworks_and_a_star():
    rocket = modified({"function": "set_fireworks", "flight_duration": 2, "explosions": {
        "mode": "append", "values": [{"shape": "star", "colors": [255], "has_twinkle": True}]}},
        "minecraft:firework_rocket")
    assert component(rocket, "fireworks") == \
        '{explosions:[{colors:[I;255],has_twinkle:1b,shape:"star"}],flight_duration:2b}'
    # the function's own flag names (trail, twinkle) over FireworkExplosion.DEFAULT, a small ball
    star = modified({"function": "set_firework_explosion", "trail": True, "fade_colors": [1, 2]},
                    "minecraft:firework_star")
    assert component(star, "firework_explosion") == '{fade_colors:[I;1,2],has_trail:1b,shape:"small_ball"}'


def test_banner_patterns_append_or_replace():
    layer = {"pattern": "minecraft:stripe_top", "color": "red"}
    banner = modified([{"function": "set_banner_pattern", "patterns": [layer], "append": False},
                       {"function": "set_banner_pattern", "patterns": [{**layer, "color": "blue"}], "append": True}],
                      "minecraft:white_banner")
    assert component(banner, "banner_patterns") == \
        '[{color:"red",pattern:"minecraft:stripe_top"},{color:"blue",pattern:"minecraft:stripe_top"}]'
    banner = modified({"function": "set_banner_pattern", "patterns": [layer], "append": False}, "minecraft:white_banner")
    assert component(banner, "banner_patterns") == '[{color:"red",pattern:"minecraft:stripe_top"}]'


def test_discard_leaves_nothing():
    assert modified({"function": "discard"}, "minecraft:stone", (1, 21, 5)).is_empty


def test_lore_beyond_its_end_is_left_as_it_was():
    # SetLoreFunction runs the same ListOperation: replace_section past the end is refused
    stack = modified([{"function": "set_lore", "lore": ["a"]},
                      {"function": "set_lore", "lore": ["b"], "mode": "replace_section", "offset": 3}], "minecraft:stone")
    assert [str(line) for line in stack.component("minecraft:lore")] == ['"a"']
