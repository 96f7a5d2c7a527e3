"""Item predicates and every item sub-predicate (``name~value`` in commands, ``predicates`` in JSON)."""
from __future__ import annotations

import pytest

from emulator.world import items
from emulator.world.errors import Unmodelled
from emulator.world.item_predicates import codec_matches, matches
from emulator.world.loot_context import to_tag
from emulator.world.resources import Resources
from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.items import item_argument, item_predicate
from mcfunction_parser.pack.registry_tags import RegistryTag
from mcfunction_parser.reader import ParseError, Reader

V121, V1215, V12111, V1206 = (1, 21, 0), (1, 21, 5), (1, 21, 11), (1, 20, 6)


def argument(text, version=V121):
    return item_argument(Reader(text, Loc("t", 1, 1), version))


def predicate(text, version=V121):
    return item_predicate(Reader(text, Loc("t", 1, 1), version))


def holds(stack_text, predicate_text, version=V121, resources=None):
    stack = items.create(argument(stack_text, version), 1)
    return matches(predicate(predicate_text, version), stack, resources or Resources(), version)


@pytest.mark.parametrize("text,expected", [
    ("minecraft:diamond_sword", True), ("*", True), ("stone", False),
    ("*[damage=3]", True), ("*[damage=4]", False), ("*[!damage]", False), ("*[custom_name]", False),
    ("*[custom_data~{a:1b}]", True), ("*[custom_data~{a:2b}]", False), ("*[damage~{durability:1558}]", True),
    ("*[count={min:2}]", False), ("*[count=1]", True), ("*[count~{max:1}]", True), ("*[custom_name|damage=3]", True),
    ("#t:blades", True), ("#t:other", False),
])
def test_item_predicates(text, expected):
    # ItemPredicateArgument; ItemDamagePredicate (durability = max_damage - damage); ItemCustomDataPredicate
    stack = items.create(argument("diamond_sword[damage=3,custom_data={a:1b,b:2}]"), 1)
    resources = Resources(tags={"item": {"t:blades": RegistryTag(frozenset({"minecraft:diamond_sword"})),
                                         "t:other": RegistryTag(frozenset())}})
    assert matches(predicate(text), stack, resources, V121) is expected


@pytest.mark.parametrize("text,expected", [
    ("*[enchantments~[]]", True), ("*[enchantments~[{}]]", True),
    ("*[enchantments~[{enchantments:'minecraft:sharpness'}]]", True),
    ("*[enchantments~[{enchantments:'sharpness',levels:{min:3}}]]", True),
    ("*[enchantments~[{enchantments:'minecraft:sharpness',levels:4}]]", False),
    ("*[enchantments~[{enchantments:['minecraft:smite','minecraft:unbreaking'],levels:{max:1}}]]", True),
    ("*[enchantments~[{enchantments:'minecraft:smite'}]]", False),
    ("*[enchantments~[{levels:{min:3}}]]", True), ("*[enchantments~[{levels:{min:4}}]]", False),
    ("*[enchantments~[{enchantments:'#t:damage'}]]", True), ("*[enchantments~[{enchantments:'#t:none'}]]", False),
    ("*[enchantments~[{enchantments:'minecraft:sharpness'},{enchantments:'minecraft:smite'}]]", False),
    ("*[stored_enchantments~[{}]]", False),
])
def test_enchantment_sub_predicates(text, expected):
    # ItemEnchantmentsPredicate: each EnchantmentPredicate.containedIn the component: with
    # `enchantments` (an id, a list, a #tag) one present at a level within `levels`; without, any
    # enchantment within `levels`, or any enchantment at all when the levels bound nothing
    stack = items.create(argument("diamond_sword[enchantments={levels:{'minecraft:sharpness':3,"
                                  "'minecraft:unbreaking':1}}]"), 1)
    resources = Resources(tags={"enchantment": {"t:damage": RegistryTag(frozenset({"minecraft:sharpness"})),
                                                "t:none": RegistryTag(frozenset())}})
    assert matches(predicate(text), stack, resources, V121) is expected
    plain = items.create(argument("diamond_sword"), 1)
    assert not matches(predicate("*[enchantments~[{}]]"), plain, resources, V121)
    # the short form of the component, ids without their namespace: the codec reads them as the
    # enchantments' holders (ItemEnchantments.CODEC), so the predicate finds them by full id
    short = items.create(argument("iron_chestplate[enchantments={binding_curse:1}]"), 1)
    assert short.patch["minecraft:enchantments"] == {"minecraft:binding_curse": 1}  # saved by full id
    book = items.create(argument("enchanted_book[stored_enchantments={levels:{mending:1}}]"), 1)
    assert book.patch["minecraft:stored_enchantments"] == {"levels": {"minecraft:mending": 1}}
    for wanted, found in (("'minecraft:binding_curse',levels:1", True), ("'binding_curse'", True),
                          ("'minecraft:sharpness'", False)):
        assert matches(predicate(f"*[enchantments~[{{enchantments:{wanted}}}]]"), short, resources, V121) is found



def test_damage_needs_the_damage_component_and_reads_max_damage_as_zero_without_one():
    # ItemDamagePredicate is a SingleComponentItemPredicate on DAMAGE: a stack without it fails;
    # durability is ItemStack.getMaxDamage() (0 without max_damage) less the damage
    assert not holds("stone", "*[damage~{}]")
    assert holds("stone[damage=3]", "*[damage~{durability:-3,damage:3}]")
    assert not holds("diamond_sword[!damage]", "*[damage~{}]")


@pytest.mark.parametrize("stack,text,expected", [
    ("potion[potion_contents={potion:'minecraft:healing'}]", "*[potion_contents~'minecraft:healing']", True),
    ("potion[potion_contents={potion:'minecraft:healing'}]", "*[potion_contents~['swiftness','healing']]", True),
    ("potion[potion_contents={potion:'minecraft:healing'}]", "*[potion_contents~'minecraft:swiftness']", False),
    ("potion[potion_contents={potion:'minecraft:healing'}]", "*[potion_contents~'#t:good']", True),
    ("potion[potion_contents='minecraft:healing']", "*[potion_contents~healing]", True),
    ("potion[potion_contents={custom_color:3}]", "*[potion_contents~'minecraft:healing']", False),
    ("stone", "*[potion_contents~'minecraft:healing']", False),
])
def test_potion_contents(stack, text, expected):
    # ItemPotionsPredicate: PotionContents.potion() in the HolderSet; no potion (custom colours or
    # effects only) or no component: false
    resources = Resources(tags={"potion": {"t:good": RegistryTag(frozenset({"minecraft:healing"}))}})
    assert holds(stack, text, resources=resources) is expected


BOX = ("shulker_box[container=[{slot:0,item:{id:'minecraft:stone',count:3}},"
       "{slot:5,item:{id:'minecraft:dirt',count:1,components:{'minecraft:custom_data':{a:1b}}}}]]")


@pytest.mark.parametrize("text,expected", [
    ("*[container~{}]", True),
    ("*[container~{items:{contains:[{items:'minecraft:stone',count:{min:2}}]}}]", True),
    ("*[container~{items:{contains:[{items:'minecraft:stone'},{items:'minecraft:dirt'}]}}]", True),
    ("*[container~{items:{contains:[{items:'minecraft:stone'},{items:'minecraft:diamond'}]}}]", False),
    # one stack takes away every predicate it matches (CollectionContentsPredicate.Multiple)
    ("*[container~{items:{contains:[{items:'minecraft:stone'},{count:3}]}}]", True),
    ("*[container~{items:{count:[{test:{items:'minecraft:stone'},count:1}]}}]", True),
    ("*[container~{items:{count:[{test:{},count:2},{test:{items:'#t:soil'},count:1}]}}]", True),
    ("*[container~{items:{count:[{test:{items:'minecraft:stone'},count:2}]}}]", False),
    ("*[container~{items:{size:2}}]", True), ("*[container~{items:{size:{min:3}}}]", False),
    ("*[container~{items:{contains:[{predicates:{'minecraft:custom_data':{a:1b}}}]}}]", True),
    ("*[container~{items:{contains:[{components:{'minecraft:custom_data':{a:1b}}}]}}]", True),
    ("*[container~{items:{contains:[{predicates:{'minecraft:custom_data':'{a:2b}'}}]}}]", False),
])
def test_container(text, expected):
    # ItemContainerPredicate: a CollectionPredicate (contains, count, size) of ItemPredicates over
    # ItemContainerContents.nonEmptyItems
    resources = Resources(tags={"item": {"t:soil": RegistryTag(frozenset({"minecraft:dirt"}))}})
    assert holds(BOX, text, resources=resources) is expected


def test_container_defaults_and_bundles():
    # Items: a shulker box (and chests, barrels ...) has an empty container by default, a bundle an
    # empty bundle_contents, stone neither (SingleComponentItemPredicate: absent fails)
    assert holds("shulker_box", "*[container~{items:{size:0}}]")
    assert holds("barrel", "*[container~{}]") and not holds("stone", "*[container~{}]")
    assert holds("bundle", "*[bundle_contents~{items:{size:0}}]")
    bundle = "bundle[bundle_contents=[{id:'minecraft:stone',count:4},{id:'minecraft:stick',count:2}]]"
    assert holds(bundle, "*[bundle_contents~{items:{contains:[{items:'minecraft:stick',count:2}]}}]")
    assert not holds(bundle, "*[bundle_contents~{items:{contains:[{items:'minecraft:stick',count:3}]}}]")
    assert not holds("stone", "*[bundle_contents~{}]")
    # a set_contents equal to the default leaves the patch, as PatchedDataComponentMap.set does
    assert items.create(argument("chest[container=[]]"), 1).patch == {}


@pytest.mark.parametrize("stack,text,expected", [
    ("firework_star[firework_explosion={shape:'star',has_trail:true}]", "*[firework_explosion~{shape:'star'}]", True),
    ("firework_star[firework_explosion={shape:'star',has_trail:true}]", "*[firework_explosion~{has_twinkle:true}]", False),
    ("firework_star[firework_explosion={shape:'star',has_trail:true}]",
     "*[firework_explosion~{has_twinkle:false,has_trail:true}]", True),
    ("firework_star", "*[firework_explosion~{}]", False),
    ("firework_rocket", "*[fireworks~{flight_duration:1}]", True),
    ("firework_rocket[fireworks={flight_duration:3b,explosions:[{shape:'burst'},{shape:'creeper'}]}]",
     "*[fireworks~{explosions:{contains:[{shape:'creeper'}],size:2},flight_duration:{min:2}}]", True),
    ("firework_rocket[fireworks={flight_duration:3b,explosions:[{shape:'burst'}]}]",
     "*[fireworks~{explosions:{contains:[{shape:'star'}]}}]", False),
])
def test_fireworks(stack, text, expected):
    # ItemFireworkExplosionPredicate.FireworkPredicate (shape, has_twinkle, has_trail: absent is
    # false in FireworkExplosion); ItemFireworksPredicate (explosions, flight_duration); a rocket's
    # default Fireworks(1, []) (Items.FIREWORK_ROCKET)
    assert holds(stack, text) is expected


def test_books():
    # ItemWritableBookPredicate: a page predicate is the page's raw text (Filterable: a string or
    # {raw, filtered})
    book = "writable_book[writable_book_content={pages:[{raw:'hello'},{raw:'x',filtered:'y'}]}]"
    assert holds(book, "*[writable_book_content~{pages:{contains:['x','hello'],size:2}}]")
    assert not holds(book, "*[writable_book_content~{pages:{contains:['y']}}]")
    assert holds("writable_book", "*[writable_book_content~{pages:{size:0}}]")
    # ItemWrittenBookPredicate: author, the raw title, generation (0), resolved (false); a page
    # predicate is a text component (ComponentSerialization.CODEC: a string is plain text) while the
    # book keeps JSON strings before 1.21.5 (WrittenBookContent.CONTENT_CODEC: flatCodec)
    old = "written_book[written_book_content={title:{raw:'T'},author:'A',pages:['\"hi\"','{\"text\":\"yo\"}']}]"
    assert holds(old, "*[written_book_content~{author:'A',title:'T',generation:0,resolved:false}]")
    assert holds(old, "*[written_book_content~{pages:{contains:['hi']}}]")
    assert holds(old, "*[written_book_content~{pages:{contains:[{text:'hi'},{text:'yo'}]}}]")
    assert not holds(old, "*[written_book_content~{pages:{contains:['{\"text\":\"yo\"}']}}]")
    assert not holds(old, "*[written_book_content~{generation:{min:1}}]")
    new = "written_book[written_book_content={title:'T',author:'A',pages:['hi',{text:'yo',bold:true}]}]"
    assert holds(new, "*[written_book_content~{pages:{contains:[{text:'hi'},{text:'yo',bold:true}]}}]", V1215)
    assert holds(new, "*[written_book_content~{pages:{contains:['hi',{text:'yo',bold:1b}]}}]", V1215)
    assert not holds(new, "*[written_book_content~{pages:{contains:['yo']}}]", V1215)


def test_attribute_modifiers_trims_songs_and_villager_variants():
    # ItemAttributeModifiersPredicate.EntryPredicate (attribute, id, amount, operation, slot; every
    # item has the component, empty by default)
    sword = ("diamond_sword[attribute_modifiers={modifiers:[{type:'minecraft:generic.attack_damage',id:'x:y',"
             "amount:5.0,operation:'add_value',slot:'mainhand'}]}]")
    assert holds(sword, "*[attribute_modifiers~{modifiers:{contains:[{attribute:'generic.attack_damage',"
                        "amount:{min:4.0},slot:'mainhand',id:'x:y'}]}}]")
    assert not holds(sword, "*[attribute_modifiers~{modifiers:{contains:[{operation:'add_multiplied_base'}]}}]")
    assert holds("stone", "*[attribute_modifiers~{}]") and not holds("stone", "*[attribute_modifiers~{modifiers:{size:1}}]")
    # ... unless the patch removed it (the removal of a default is kept: PatchedDataComponentMap)
    assert not holds("stone[!attribute_modifiers]", "*[attribute_modifiers~{}]")
    assert holds("stone", "*[enchantments~[]]") and not holds("stone[!enchantments]", "*[enchantments~[]]")
    # Items.ENCHANTED_BOOK: stored_enchantments, empty by default
    assert holds("enchanted_book", "*[stored_enchantments~[]]") and not holds("book", "*[stored_enchantments~[]]")
    # ItemTrimPredicate: the material and pattern in their HolderSets; an inline material in none
    chest = "iron_chestplate[trim={material:'minecraft:gold',pattern:'minecraft:coast'}]"
    assert holds(chest, "*[trim~{material:'minecraft:gold',pattern:['minecraft:coast','minecraft:dune']}]")
    assert not holds(chest, "*[trim~{pattern:'minecraft:dune'}]")
    assert not holds("iron_chestplate[trim={material:{asset_name:'x',ingredient:'stone',item_model_index:0.5f,"
                     "description:'x'},pattern:'minecraft:coast'}]", "*[trim~{material:'minecraft:gold'}]")
    # ItemJukeboxPlayablePredicate: a music disc's own song (Items: music_disc_<song>)
    assert holds("music_disc_cat", "*[jukebox_playable~{song:'minecraft:cat'}]")
    assert not holds("music_disc_cat", "*[jukebox_playable~{song:['minecraft:13']}]")
    assert holds("music_disc_13", "*[jukebox_playable~{}]") and not holds("stone", "*[jukebox_playable~{}]")
    # JukeboxPlayable.CODEC: {song} before 1.21.5, the song alone from it; either way the disc's own
    # song is its default (the patch stays empty) and equals the component as written
    assert holds("music_disc_cat", "*[jukebox_playable={song:'minecraft:cat'}]")
    assert holds("music_disc_cat", "*[jukebox_playable='minecraft:cat']", V1215)
    assert items.create(argument("music_disc_cat[jukebox_playable='minecraft:cat']", V1215), 1).patch == {}
    assert not holds("music_disc_cat", "*[jukebox_playable={song:'minecraft:cat',show_in_tooltip:false}]")
    # VillagerTypePredicate (DataComponentPredicates, read from 1.21.11)
    assert holds("stone[villager/variant='minecraft:desert']", "*[villager/variant~'minecraft:desert']", V12111)
    assert not holds("stone[villager/variant='minecraft:desert']", "*[villager/variant~['taiga']]", V12111)
    with pytest.raises(ParseError, match="unknown item sub-predicate"):
        predicate("*[villager/variant~'minecraft:desert']", V121)


def test_a_sub_predicate_the_release_lacks_is_reported_not_false():
    # not registered in the release (the game would refuse the predicate): reported, never false
    later = predicate("*[villager/variant~'minecraft:desert']", V12111)
    with pytest.raises(Unmodelled, match="villager/variant"):
        matches(later, items.ItemStack("minecraft:stone"), Resources(), V121)
    with pytest.raises(Unmodelled, match="custom_name"):
        codec_matches(to_tag({"predicates": {"minecraft:custom_name": {}}}), items.ItemStack("minecraft:stone"),
                      Resources(), V121)


def test_the_codec_form_reads_json():
    # ItemPredicate.CODEC over JSON (predicate files, advancements): items, count, components, predicates
    stack = items.create(argument(BOX), 1)
    wanted = {"items": ["minecraft:shulker_box"], "count": {"min": 1},
              "predicates": {"container": {"items": {"contains": [{"items": "minecraft:dirt",
                                                                  "predicates": {"custom_data": "{a:1b}"}}]}}}}
    assert codec_matches(to_tag(wanted), stack, Resources(), V121)
    wanted["count"] = 2
    assert not codec_matches(to_tag(wanted), stack, Resources(), V121)
