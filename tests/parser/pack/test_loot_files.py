"""Loot tables and item modifiers as the loader reads them: checked as the game decodes them, a
problem reported at its line and column, a file that does not decode left out (the game skips
it), the rest of the pack loaded."""
from __future__ import annotations

import json

from mcfunction_parser import load_packs
from tests.conftest import write_pack

GOOD = {"pools": [{"rolls": 1, "entries": [{"type": "minecraft:item", "name": "minecraft:stone"}]}]}


def test_valid_files_load_with_their_folder_names(tmp_path):
    root = write_pack(tmp_path / "p", {"a/loot_table/x.json": json.dumps(GOOD),
                                       "a/item_modifier/m.json": json.dumps([{"function": "set_count", "count": 2}]),
                                       "a/tags/item/t.json": json.dumps({"values": ["stone"]})})
    packs = load_packs([root])
    assert packs.errors == [] and set(packs.loot_tables) == {"a:x"} and set(packs.item_modifiers) == {"a:m"}
    assert packs.registry_tags["item"]["a:t"].members == {"minecraft:stone"}


def test_older_packs_read_the_plural_folders(tmp_path):
    root = write_pack(tmp_path / "p", {"a/loot_tables/x.json": json.dumps(GOOD), "a/loot_table/y.json": json.dumps(GOOD)})
    (root / "pack.mcmeta").write_text(json.dumps({"pack": {"pack_format": 26, "description": ""}}))
    packs = load_packs([root])
    assert set(packs.loot_tables) == {"a:x"}
    assert any("ignored" in w.message for w in packs.warnings)


def test_problems_name_the_place_and_the_file_is_left_out(tmp_path):
    text = ('{\n  "pools": [\n    {"rolls": 1, "entries": [\n      {"type": "minecraft:item", "name": "stone",\n'
            '       "functions": [{"function": "minecraft:set_colour"}]}]}\n  ]\n}\n')
    root = write_pack(tmp_path / "p", {"a/loot_table/bad.json": text, "a/loot_table/good.json": json.dumps(GOOD),
                                       "a/loot_table/broken.json": '{"pools": [}',
                                       "a/item_modifier/m.json": '{"function": "set_count", "count": {"type": "gaussian"}}',
                                       "a/function/f.mcfunction": "say hi\n"})
    packs = load_packs([root])
    found = sorted((e.path.rsplit("/", 1)[-1], e.line, e.col, e.message) for e in packs.errors)
    assert found == [
        ("bad.json", 5, 35, "unknown item function type 'minecraft:set_colour'"),
        ("broken.json", 1, 12, "invalid JSON: Expecting value"),
        ("m.json", 1, 45, "unknown number provider type 'gaussian'"),
    ]
    assert set(packs.loot_tables) == {"a:good"} and "a:f" in packs.functions


def test_types_are_checked_for_the_version(tmp_path):
    # LootItemFunctions: set_nbt was replaced by set_custom_data/set_components in 1.20.5
    root = write_pack(tmp_path / "p", {"a/item_modifier/m.json": json.dumps({"function": "set_nbt", "tag": "{}"})})
    assert [e.message for e in load_packs([root]).errors] == ["item function type 'set_nbt' does not exist in this version"]
    assert load_packs([root], mc_version="1.20.4").errors == []


def test_conditions_are_checked_as_predicate_files_are(tmp_path):
    # LootItemConditions' codec, the same in a loot table as in a predicate file: the release's
    # types (alternative until 1.20, any_of from then) and the required fields
    pool = {"rolls": 1, "entries": [{"type": "item", "name": "stone"}],
            "conditions": [{"condition": "alternative", "terms": []}, {"condition": "entity_scores", "entity": "this"}]}
    root = write_pack(tmp_path / "p", {"a/loot_table/x.json": json.dumps({"pools": [pool]})})
    found = [(e.line, e.message) for e in load_packs([root], mc_version="1.21").errors]
    assert found == [(1, "unknown predicate condition type 'alternative' in this release (it exists from 1.13.0 until "
                         "1.20.0)"), (1, "condition 'entity_scores' needs the field \"scores\"")]
    pool["conditions"] = [{"condition": "alternative", "terms": []}]
    old = write_pack(tmp_path / "old", {"a/loot_tables/x.json": json.dumps({"pools": [pool]})})
    loaded = load_packs([old], mc_version="1.19.4")
    assert loaded.errors == [] and set(loaded.loot_tables) == {"a:x"}


def test_check_names_loot_tables_and_modifiers_that_are_not_loaded(tmp_path):
    from mcfunction_parser.check import check_packs
    root = write_pack(tmp_path / "p", {"a/loot_table/x.json": json.dumps(GOOD),
                                       "a/function/f.mcfunction": "loot give @a loot a:x\nloot give @a loot a:y\n"
                                       "item modify entity @s weapon a:m\nloot give @a loot minecraft:chests/x\n"
                                       "loot give @a loot other:z\n"})
    result = check_packs([root])
    assert [(e.line, e.message) for e in result.of("error")] == [(2, "unknown loot table a:y"),
                                                                  (3, "unknown item modifier a:m")]
    # a namespace no loaded pack defines: a pack expected beside this one (the vanilla tables are
    # judged only with --game-jar)
    [warning] = [w for w in result.of("warning") if "other:z" in w.message]
    assert warning.line == 5 and warning.message.startswith(
        "unknown loot table other:z: no loaded pack defines the namespace 'other' (the command fails")


def test_item_ids_and_components_are_checked(tmp_path):
    # items are a static registry: an unknown id in a loot table fails to decode, as does a
    # component the release does not have (set_components)
    table = {"pools": [{"rolls": 1, "entries": [
        {"type": "item", "name": "minecraft:diamondd"},
        {"type": "item", "name": "stone", "functions": [{"function": "set_components",
                                                         "components": {"minecraft:bogus": 1, "!food": {}}}]}]}]}
    root = write_pack(tmp_path / "p", {"a/loot_table/x.json": json.dumps(table, indent=1)})
    packs = load_packs([root], mc_version="1.21.4")
    assert sorted((e.line, e.message) for e in packs.errors) == [
        (8, "unknown item 'minecraft:diamondd'"), (17, "unknown component 'minecraft:bogus'")]
    assert packs.loot_tables == {}
