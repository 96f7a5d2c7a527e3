"""Translated text as a server reads it (Component.getString of TranslatableContents)."""
from __future__ import annotations

import json

import pytest

from emulator.world.text import plain_text


def read(component, release=(1, 21, 4)) -> str:
    return plain_text(json.dumps(component), release)


@pytest.mark.parametrize("component, text", [
    # TranslatableContents.decompose: the key's en_us string, its %s taking the arguments in turn
    ({"translate": "chat.type.text", "with": ["Alex", "hi"]}, "<Alex> hi"),
    # decomposeTemplate: %N$s names an argument, %% is a percent sign; a key the language lacks is
    # its own template (Language.getOrDefault)
    ({"translate": "%2$s, %1$s and %%", "with": ["a", {"text": "b"}]}, "b, a and %"),
    # ... and anything it cannot decompose is shown as written: another conversion, a stray %, an
    # argument index past the end (TranslatableFormatException)
    ({"translate": "%d items", "with": [1]}, "%d items"),
    ({"translate": "100%"}, "100%"),
    ({"translate": "%s and %s", "with": ["one"]}, "%s and %s"),
    # getArgument: a primitive argument reads as its toString; extra arguments are left over
    ({"translate": "%s %s %s", "with": [3, 2.5, True, "unused"]}, "3 2.5 true"),
    # a component argument is read whole, with its own extras and translations
    ({"translate": "[%s]", "with": [{"translate": "item.minecraft.diamond", "extra": ["!"]}]}, "[Diamond!]"),
    # the fallback stands in for a key the language lacks (23w03a, 1.19.4)
    ({"translate": "mypack.greeting", "fallback": "Hello %s", "with": ["Alex"]}, "Hello Alex"),
    ({"translate": "item.minecraft.diamond", "fallback": "x"}, "Diamond"),
    # KeybindContents on a server: the key's translation (KeybindResolver's default)
    ({"keybind": "key.jump"}, "Jump"),
    # ComponentSerialization takes the first content type whose field is there: text, then translate
    ({"text": "a", "translate": "item.minecraft.diamond"}, "a"),
    ({"translate": "item.minecraft.diamond", "keybind": "key.jump"}, "Diamond"),
])
def test_translations_read_as_on_a_server(component, text):
    assert read(component) == text


def test_the_strings_are_the_releases_own():
    # netherite came with 1.16: 1.15's en_us has no key for it, so the key reads as itself
    ingot = {"translate": "item.minecraft.netherite_ingot"}
    assert (read(ingot, (1, 15, 2)), read(ingot, (1, 16, 5))) == ("item.minecraft.netherite_ingot", "Netherite Ingot")


def test_fallback_is_ignored_before_1_19_4():
    component = {"translate": "mypack.greeting", "fallback": "Hello"}
    assert (read(component, (1, 19, 3)), read(component, (1, 19, 4))) == ("mypack.greeting", "Hello")


def test_without_a_release_only_fallbacks_and_keys():
    assert plain_text('{"translate":"item.minecraft.diamond"}') == "item.minecraft.diamond"
    assert plain_text('{"translate":"x","fallback":"y"}') == "y"


def test_entities_are_named_by_their_types_and_items_by_theirs(tmp_path):
    # Entity.getName: EntityType.getDescription (en_us "entity.minecraft.tnt_minecart"); an item
    # entity's ItemEntity.getName: the stack's item name (ItemStack.getItemName: item_name, else the
    # item's en_us name, a block item's its block's), never the stack's custom name
    from tests.world.world_emulator import emulator
    emu = emulator(tmp_path, "python", {"t:main": "\n".join([
        "summon tnt_minecart 0 0 0",
        'summon item 0 0 0 {Item:{id:"minecraft:stone",count:1}}',
        'summon item 0 0 0 {Item:{id:"minecraft:redstone",count:1,components:{"minecraft:custom_name":\'"X"\'}}}',
        'summon item 0 0 0 {Item:{id:"minecraft:diamond",count:1,components:{"minecraft:item_name":\'"Gem"\'}}}',
        'tellraw @a {"selector":"@e[type=!player]"}'])})
    emu.add_player("Alex")
    emu.call("t:main")
    assert emu.log[0].read_text(emu.state.version) == "Minecart with TNT, Stone, Redstone Dust, Gem"



def test_a_stack_is_named_by_its_custom_name_or_its_items():
    # ItemStack.getHoverName: custom_name, else the item's name (a block item's is its block's
    # en_us name); getDisplayName puts it in brackets, as GiveCommand's ERROR_TOO_MANY_ITEMS shows it
    from types import SimpleNamespace

    from emulator.commands.items import _name
    from emulator.world import items
    from emulator.world.errors import CommandFailure
    from mcfunction_parser.nbt import Compound, String
    release = (1, 21, 4)
    assert items.hover_name(items.ItemStack("minecraft:oak_sign"), release) == "Oak Sign"
    named = items.ItemStack("minecraft:stone", 1, Compound({"minecraft:custom_name": String('"Rock"')}))
    assert items.hover_name(named, release) == "Rock"
    env = SimpleNamespace(state=SimpleNamespace(version=release))
    failure = CommandFailure("commands.give.failed.toomanyitems", 100, _name(env, items.ItemStack("minecraft:diamond_sword")))
    assert failure.message == "Can't give more than 100 of [Diamond Sword]"
