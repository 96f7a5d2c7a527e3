"""Registry tags, predicates and advancements as the loader reads them (TagLoader, the predicate and
advancement codecs; minecraft.wiki "Tag", "Predicate", "Advancement definition")."""
import json
import zipfile

import pytest

from mcfunction_parser.gamedata.vanilla_tags import GameJarError
from mcfunction_parser.pack.loader import load_packs
from tests.parser.pack.packbuild import meta, tag, write_pack


def test_registry_tags_merge_nest_and_fail_like_the_game(tmp_path):
    lib = write_pack(tmp_path / "lib", {"data/a/tags/block/soft.json": tag("minecraft:sand"),
                                        "data/a/tags/item/gone.json": tag("minecraft:stick")}, meta(48))
    pack = write_pack(tmp_path / "pack", {
        "data/a/tags/block/soft.json": tag("minecraft:gravel"),               # appends
        "data/a/tags/item/gone.json": tag("minecraft:apple", replace=True),   # replaces
        "data/a/tags/block/outer.json": tag("#a:soft", {"id": "#a:none", "required": False}),
        "data/a/tags/block/broken.json": tag("#a:none"),                      # a required tag missing
        "data/a/tags/block/uses_broken.json": tag("#a:broken"),
        "data/a/tags/blocks/old.json": tag("minecraft:stone"),                # 1.21 reads block/
        "data/a/tags/worldgen/biome/warm.json": tag("minecraft:desert"),
    }, meta(48))
    loaded = load_packs([lib, pack])
    tags = loaded.registry_tags
    assert tags["block"]["a:soft"].members == {"minecraft:sand", "minecraft:gravel"}
    assert tags["item"]["a:gone"].members == {"minecraft:apple"}
    assert tags["block"]["a:outer"].members == {"minecraft:sand", "minecraft:gravel"}
    assert "a:broken" not in tags["block"] and "a:uses_broken" not in tags["block"]
    assert tags["worldgen/biome"]["a:warm"].members == {"minecraft:desert"}
    messages = [d.message for d in loaded.diagnostics]
    assert "block tag #a:broken fails to load: #a:none does not exist" in messages
    assert any("'data/a/tags/blocks/' ignored" in m and "reads 'data/a/tags/block/'" in m for m in messages)
    # before 1.21 (format 41) the plural folder is the one read
    old = load_packs([pack], mc_version="1.20.6")
    assert old.registry_tags["block"]["a:old"].members == {"minecraft:stone"}


def test_unknown_vanilla_tags_are_kept_unknown_without_a_jar(tmp_path):
    pack = write_pack(tmp_path / "p", {"data/a/tags/block/logs.json": tag("#minecraft:logs", "minecraft:dirt")}, meta(48))
    loaded = load_packs([pack])
    assert loaded.registry_tags["block"]["a:logs"].unknown == ("minecraft:logs",)
    assert loaded.errors == []


def test_game_jar_tags_load_under_the_packs(tmp_path):
    jar = tmp_path / "client.jar"
    with zipfile.ZipFile(jar, "w") as archive:
        archive.writestr("data/minecraft/tags/block/logs.json", tag("minecraft:oak_log", "#minecraft:birch"))
        archive.writestr("data/minecraft/tags/block/birch.json", tag("minecraft:birch_log"))
        archive.writestr("data/minecraft/loot_table/entities/cow.json", '{"pools": []}')
        archive.writestr("data/minecraft/loot_table/chests/x.json", '{"pools": []}')
    server = tmp_path / "server.jar"  # a bundler: the real server jar nested inside
    with zipfile.ZipFile(server, "w") as archive:
        archive.writestr("META-INF/versions/1.21/server-1.21.jar", jar.read_bytes())
    pack = write_pack(tmp_path / "p", {"data/minecraft/tags/block/logs.json": tag("minecraft:dirt"),
                                       "data/minecraft/loot_table/chests/x.json": '{"pools": [], "random_sequence": "a"}'},
                      meta(48))
    for given in (jar, server):
        loaded = load_packs([pack], game_jar=given)
        assert loaded.vanilla_data
        assert loaded.registry_tags["block"]["minecraft:logs"].members == {
            "minecraft:oak_log", "minecraft:birch_log", "minecraft:dirt"}
        # the game's loot tables load first, a pack's file of the same id replaces one
        assert loaded.loot_tables["minecraft:entities/cow"].value == {"pools": []}
        assert "random_sequence" in loaded.loot_tables["minecraft:chests/x"].value
    with pytest.raises(GameJarError):
        load_packs([pack], game_jar=pack / "pack.mcmeta")


def test_predicates_that_fail_to_load_are_errors_with_their_position(tmp_path):
    pack = write_pack(tmp_path / "p", {
        "data/a/predicate/ok.json": json.dumps({"condition": "minecraft:any_of", "terms": []}),
        "data/a/predicate/bad_type.json": '{\n  "condition": "minecraft:nope"\n}',
        "data/a/predicate/old_type.json": json.dumps({"condition": "alternative", "terms": []}),
        "data/a/predicate/missing.json": json.dumps({"condition": "minecraft:entity_scores", "entity": "this"}),
        "data/a/predicate/syntax.json": '{"condition": ',
    }, meta(48))
    loaded = load_packs([pack])
    assert set(loaded.predicates) == {"a:ok"}
    found = {d.path.rsplit("/", 1)[1]: d for d in loaded.errors}
    assert (found["bad_type.json"].line, found["bad_type.json"].col) == (2, 16)
    assert "unknown predicate condition type 'minecraft:nope'" in found["bad_type.json"].message
    # LootItemConditions: 1.20 registers any_of in place of alternative
    assert "until 1.20" in found["old_type.json"].message
    assert 'needs the field "scores"' in found["missing.json"].message
    assert "invalid JSON" in found["syntax.json"].message


def test_advancements_load_with_their_criteria(tmp_path):
    good = {"criteria": {"t": {"trigger": "minecraft:tick"}}, "rewards": {"function": "a:r"}}
    pack = write_pack(tmp_path / "p", {
        "data/a/advancement/good.json": json.dumps(good),
        "data/a/advancement/bad.json": json.dumps({"criteria": {"x": {"trigger": "minecraft:flying"}}}),
        "data/a/advancement/req.json": json.dumps({"criteria": {"x": {"trigger": "minecraft:impossible"}},
                                                   "requirements": [["y"]]}),
    }, meta(48))
    loaded = load_packs([pack])
    assert set(loaded.advancements) == {"a:good"}
    messages = sorted(d.message for d in loaded.errors)
    assert messages == ["advancement a:bad fails to load: unknown criterion trigger 'minecraft:flying'",
                        "advancement a:req fails to load: requirements name 'y', which is not a criterion"]
    assert list(loaded.advancement_rewards) == ["a:r"]


def test_an_item_sub_predicate_the_release_lacks_refuses_the_file(tmp_path):
    # ItemSubPredicate.CODEC is a dispatched map over the registry: an unknown name fails the whole
    # file (custom_name is a component, not a sub-predicate; villager/variant comes with 1.21.11)
    def tool(subs):
        return json.dumps({"condition": "minecraft:match_tool", "predicate": {"predicates": subs}})

    pack = write_pack(tmp_path / "p", {
        "data/a/predicate/ok.json": tool({"minecraft:container": {}, "potion_contents": "minecraft:water"}),
        "data/a/predicate/name.json": tool({"minecraft:custom_name": {}}),
        "data/a/predicate/villager.json": tool({"villager/variant": "minecraft:desert"}),
        "data/a/advancement/inv.json": json.dumps({"criteria": {"t": {
            "trigger": "minecraft:inventory_changed", "conditions": {"items": [{"predicates": {"nope": {}}}]}}}}),
    }, meta(48))
    loaded = load_packs([pack])
    assert set(loaded.predicates) == {"a:ok"} and not loaded.advancements
    assert sorted(d.message for d in loaded.errors) == [
        "advancement a:inv fails to load: unknown item sub-predicate 'nope' in this release",
        "predicate a:name fails to load: unknown item sub-predicate 'minecraft:custom_name' in this release",
        "predicate a:villager fails to load: unknown item sub-predicate 'villager/variant' in this release"]


def test_ids_inside_predicates_the_release_lacks_refuse_the_file(tmp_path):
    # ItemPredicate.CODEC (items: homogeneousList(ITEM), components: DataComponentType.CODEC keys),
    # EntityTypePredicate.CODEC, BlockPredicate.CODEC, SlotsPredicate.CODEC (SlotRanges.CODEC keys):
    # an id the release does not register fails the whole file, wherever it sits
    def entity(predicate):
        return json.dumps({"condition": "minecraft:entity_properties", "entity": "this", "predicate": predicate})

    pack = write_pack(tmp_path / "p", {
        "data/a/predicate/ok.json": entity({"type": "#minecraft:skeletons", "equipment": {"head": {
            "items": ["minecraft:stone"], "components": {"minecraft:damage": 1}}},
            "slots": {"container.*": {}}, "vehicle": {"type": "minecraft:pig"}}),
        "data/a/predicate/item.json": entity({"equipment": {"mainhand": {"items": "minecraft:no_item"}}}),
        "data/a/predicate/type.json": json.dumps({"condition": "minecraft:inverted", "term": json.loads(
            entity({"vehicle": {"type": ["minecraft:pig", "minecraft:no_mob"]}}))}),
        "data/a/predicate/slot.json": entity({"slots": {"weapon.nope": {}}}),
        "data/a/predicate/component.json": json.dumps({"condition": "minecraft:match_tool", "predicate": {
            "components": {"minecraft:no_component": 1}}}),
        "data/a/predicate/block.json": json.dumps({"condition": "minecraft:location_check", "predicate": {
            "block": {"blocks": "minecraft:no_block"}}}),
        "data/a/advancement/inv.json": json.dumps({"criteria": {"t": {
            "trigger": "minecraft:inventory_changed", "conditions": {"items": [{"items": "minecraft:no_item"}]}}}}),
        "data/a/advancement/player.json": json.dumps({"criteria": {"t": {
            "trigger": "minecraft:tick", "conditions": {"player": {"type": "minecraft:no_mob"}}}}}),
        "data/a/loot_table/l.json": json.dumps({"pools": [{"rolls": 1, "entries": [{
            "type": "minecraft:item", "name": "minecraft:stone", "conditions": [json.loads(entity(
                {"slots": {"weapon.nope": {}}}))]}]}]}),
    }, meta(48))
    loaded = load_packs([pack])
    assert set(loaded.predicates) == {"a:ok"} and not loaded.advancements and not loaded.loot_tables
    found = {d.path.rsplit("/", 1)[1]: d for d in loaded.errors}
    assert found["item.json"].message == "predicate a:item fails to load: unknown item 'minecraft:no_item'"
    assert (found["item.json"].line, found["item.json"].col) == (1, entity(
        {"equipment": {"mainhand": {"items": "minecraft:no_item"}}}).index('"minecraft:no_item"') + 1)
    assert "unknown entity type 'minecraft:no_mob'" in found["type.json"].message
    assert "unknown slot range 'weapon.nope'" in found["slot.json"].message
    assert "unknown component 'minecraft:no_component'" in found["component.json"].message
    assert "unknown block 'minecraft:no_block'" in found["block.json"].message
    assert "unknown item 'minecraft:no_item'" in found["inv.json"].message
    assert "unknown entity type 'minecraft:no_mob'" in found["player.json"].message
    assert "unknown slot range 'weapon.nope'" in found["l.json"].message


def test_a_tag_naming_an_item_block_or_entity_type_the_release_lacks_fails_to_load(tmp_path):
    # TagEntry.build looks each plain id up in its registry: a required one missing fails the tag
    # ("missing following references"); an optional one is skipped; a pack may add biomes
    pack = write_pack(tmp_path / "p", {
        "data/a/tags/item/bad.json": tag("minecraft:stone", "minecraft:no_item"),
        "data/a/tags/item/optional.json": tag("minecraft:stone", {"id": "minecraft:no_item", "required": False}),
        "data/a/tags/entity_type/bad.json": tag("a:my_mob"),
        "data/a/tags/worldgen/biome/mine.json": tag("a:my_biome"),
    }, meta(48))
    loaded = load_packs([pack])
    tags = loaded.registry_tags
    assert "a:bad" not in tags["item"] and "a:bad" not in tags["entity_type"]
    assert tags["item"]["a:optional"].members == {"minecraft:stone"}
    assert tags["worldgen/biome"]["a:mine"].members == {"a:my_biome"}
    assert sorted(d.message for d in loaded.errors) == [
        "entity_type tag #a:bad fails to load: a:my_mob is not in the entity_type registry of this release",
        "item tag #a:bad fails to load: minecraft:no_item is not in the item registry of this release"]


def test_test_environments_load_as_the_game_decodes_them(tmp_path):
    # TestEnvironmentDefinition.DIRECT_CODEC (1.21.5+): dispatched on type; an unknown type, a
    # missing field or invalid JSON refuses the file at its line and column; before 1.21.5 the
    # folder is not read
    pack = write_pack(tmp_path / "p", {
        "data/a/test_environment/ok.json": json.dumps({"type": "minecraft:all_of", "definitions": [
            "a:night", {"type": "minecraft:function", "setup": "a:setup"}]}),
        "data/a/test_environment/night.json": json.dumps({"type": "time_of_day", "time": 13000}),
        "data/a/test_environment/type.json": '{\n  "type": "minecraft:snowy"\n}',
        "data/a/test_environment/time.json": json.dumps({"type": "time_of_day", "time": -1}),
        "data/a/test_environment/nested.json": json.dumps({"type": "all_of", "definitions": [{"type": "nope"}]}),
        "data/a/test_environment/syntax.json": '{"type": ',
    }, meta(71))
    loaded = load_packs([pack])
    assert set(loaded.test_environments) == {"a:ok", "a:night"}
    found = {d.path.rsplit("/", 1)[1]: d for d in loaded.errors}
    assert (found["type.json"].line, found["type.json"].col) == (2, 11)
    assert "unknown test environment type 'minecraft:snowy'" in found["type.json"].message
    assert "time_of_day needs" in found["time.json"].message and "'nope'" in found["nested.json"].message
    assert "invalid JSON" in found["syntax.json"].message
    assert not load_packs([pack], mc_version="1.21.4").test_environments
