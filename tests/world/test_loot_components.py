"""The item functions that write one component whole (:mod:`emulator.world.loot_components`), as
the game saves the component: SetBookCoverFunction, SetWritableBookPagesFunction,
SetFireworksFunction, SetFireworkExplosionFunction, SetBannerPatternFunction, SetAttributesFunction,
DiscardItem, ModifyContainerContents, and ListOperation's bounds (decompiled 1.21)."""
from __future__ import annotations

import random

import numpy as np
import pytest

from emulator.world import items, loot
from emulator.world.errors import Unmodelled
from emulator.world.loot_context import LootContext
from emulator.world.resources import Resources
from emulator.world.state import WorldState
from mcfunction_parser.nbt import Compound, Int, List, String, to_snbt

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


DAMAGE = {"attribute": "minecraft:attack_damage", "id": "t:d", "amount": 0.1, "operation": "add_value",
          "slot": "mainhand"}


def test_set_attributes_saves_the_releases_form():
    # SetAttributesFunction: the amount is getFloat (0.1F saved as a double); the entry's type is
    # the attribute's id in the release (prefixed before 1.21.2); ItemAttributeModifiers is
    # {modifiers: [...]} until 1.21.5, its list from then; slot ``any`` is not saved
    entry = '{amount:0.10000000149011612d,id:"t:d",operation:"add_value",slot:"mainhand",type:"%s"}'
    stack = modified({"function": "set_attributes", "modifiers": [DAMAGE]}, "minecraft:stone")
    assert component(stack, "attribute_modifiers") == "{modifiers:[%s]}" % (entry % "minecraft:attack_damage")
    stack = modified({"function": "set_attributes", "modifiers": [DAMAGE]}, "minecraft:stone", (1, 21, 1))
    assert component(stack, "attribute_modifiers") == "{modifiers:[%s]}" % (entry % "minecraft:generic.attack_damage")
    stack = modified({"function": "set_attributes", "modifiers": [{**DAMAGE, "slot": "any"}]}, "minecraft:stone",
                     (1, 21, 5))
    assert component(stack, "attribute_modifiers") == \
        '[{amount:0.10000000149011612d,id:"t:d",operation:"add_value",type:"minecraft:attack_damage"}]'


def test_set_attributes_without_replace_adds_to_the_items_defaults():
    # replace false: the sword's own base_attack_damage and base_attack_speed stay; a modifier of
    # the same attribute and id replaces the one there (withModifierAdded)
    steps = [{"function": "set_attributes", "replace": False, "modifiers": [DAMAGE]},
             {"function": "set_attributes", "replace": False, "modifiers": [{**DAMAGE, "amount": 2}]}]
    sword = modified(steps, "minecraft:diamond_sword")
    entries = sword.component("minecraft:attribute_modifiers")["modifiers"]
    assert [(str(e["id"]), float(e["amount"])) for e in entries] == [
        ("minecraft:base_attack_damage", 6.0), ("minecraft:base_attack_speed", float(np.float32(-2.4))), ("t:d", 2.0)]


def test_set_attributes_before_1_21_is_not_modelled():
    with pytest.raises(Unmodelled, match="set_attributes"):
        modified({"function": "set_attributes", "modifiers": [DAMAGE]}, "minecraft:stone", (1, 20, 6))


def test_modify_contents_applies_the_modifier_to_each_item():
    # ModifyContainerContents: a container's items keep their slots; one the modifier empties is gone
    chest = items.ItemStack("minecraft:chest")
    items.set_component(chest, "minecraft:container", List([
        Compound(slot=Int(0), item=Compound(id=String("minecraft:stone"), count=Int(2))),
        Compound(slot=Int(4), item=Compound(id=String("minecraft:dirt"), count=Int(1)))]))
    ctx = LootContext(WorldState(version=(1, 21, 5), resources=Resources()), random=random.Random(0))
    modifier = {"function": "modify_contents", "component": "container", "modifier": [
        {"function": "set_count", "count": 5},
        {"function": "filtered", "item_filter": {"items": "minecraft:dirt"}, "modifier": {"function": "discard"}}]}
    chest = loot.apply_modifier(modifier, chest, ctx)
    assert [(int(e["slot"]), str(e["item"]["id"]), int(e["item"]["count"]))
            for e in chest.component("minecraft:container")] == [(0, "minecraft:stone", 5)]


def test_furnace_smelt_takes_the_packs_smelting_recipe():
    # SmeltItemFunction: the recipe's result with the stack's count; an item no recipe takes while
    # the game's own recipes are unknown (no --game-jar) is not modelled, never left in silence
    recipe = {"type": "minecraft:smelting", "ingredient": "minecraft:cobblestone",
              "result": {"id": "minecraft:stone"}, "experience": 0.1}
    state = WorldState(version=V121, resources=Resources(recipes={"t:stone": "minecraft:smelting"},
                                                         recipe_bodies={"t:stone": recipe}))
    ctx = LootContext(state, random=random.Random(0))
    smelted = loot.apply_modifier({"function": "furnace_smelt"}, items.ItemStack("minecraft:cobblestone", 5), ctx)
    assert (smelted.id, smelted.count) == ("minecraft:stone", 5)
    with pytest.raises(Unmodelled, match="smelting"):
        loot.apply_modifier({"function": "furnace_smelt"}, items.ItemStack("minecraft:sand"), ctx)


def test_toggle_tooltips_hides_and_shows_components_in_order():
    # ToggleTooltips (1.21.5+): TooltipDisplay.withHidden per toggle, in the toggles' order; all
    # shown again is TooltipDisplay.DEFAULT, no patch. Before 1.21.5: not modelled
    hide = {"function": "toggle_tooltips", "toggles": {"minecraft:enchantments": False, "dyed_color": False}}
    stack = modified(hide, "minecraft:stone", (1, 21, 5))
    assert component(stack, "tooltip_display") == '{hidden_components:["minecraft:enchantments","minecraft:dyed_color"]}'
    stack = loot.apply_modifier({"function": "toggle_tooltips", "toggles": {"enchantments": True, "dyed_color": True}},
                                stack, LootContext(WorldState(version=(1, 21, 5), resources=Resources())))
    assert "minecraft:tooltip_display" not in stack.patch
    with pytest.raises(Unmodelled, match="toggle_tooltips"):
        modified(hide, "minecraft:stone")


def test_written_pages_leave_the_book_unresolved():
    # SetWrittenBookPagesFunction: the pages by ListOperation; withReplacedPages sets resolved
    # false (left out); a page is JSON text before 1.21.5 and an NBT text component from then
    steps = [{"function": "set_book_cover", "title": "T"},
             {"function": "set_written_book_pages", "pages": [{"text": "a"}, "b"], "mode": "replace_all"}]
    book = modified(steps, "minecraft:written_book")
    assert component(book, "written_book_content") == \
        """{author:"",pages:[{raw:'{"text":"a"}'},{raw:'"b"'}],title:{raw:"T"}}"""
    book = modified(steps, "minecraft:written_book", (1, 21, 5))
    assert component(book, "written_book_content") == '{author:"",pages:[{raw:{text:"a"}},{raw:"b"}],title:{raw:"T"}}'
