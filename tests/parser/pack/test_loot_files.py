"""Loot tables and item modifiers as the loader reads them: checked as the game decodes them, a
problem reported at its line and column, a file that does not decode left out (the game skips
it), the rest of the pack loaded."""
from __future__ import annotations

import json

import pytest

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
    # types (alternative 1.14 - 1.19.4, any_of from 1.20) and the required fields
    pool = {"rolls": 1, "entries": [{"type": "item", "name": "stone"}],
            "conditions": [{"condition": "alternative", "terms": []}, {"condition": "entity_scores", "entity": "this"}]}
    root = write_pack(tmp_path / "p", {"a/loot_table/x.json": json.dumps({"pools": [pool]})})
    found = [(e.line, e.message) for e in load_packs([root], mc_version="1.21").errors]
    assert found == [(1, "unknown predicate condition type 'alternative' in this release (it exists from 1.14.0 until "
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


# ---------------------------------------------------------------- required fields of item functions
# The smallest function of each type the game decodes, per release: exactly the fields its codec
# requires (from 1.20.2 the function's CODEC: RecordCodecBuilder fieldOf, while optionalFieldOf,
# strictOptionalField and fieldOf(..).orElse are optional, and ListOperation.codec's
# dispatchMap("mode") needs "mode"; before it the Serializer's deserialize: GsonHelper.getAsX(json,
# "name") with no default). Each is decompiled Mojang-mapped source of that release.
_CODEC_ERA = {  # 1.21.4 (as 1.21.3 and 1.21.7); the class's CODEC unless named otherwise
    # ApplyBonusCount: FORMULA_CODEC = ExtraCodecs.dispatchOptionalValue("formula", "parameters", ..)
    "apply_bonus": {"enchantment": "minecraft:fortune", "formula": "minecraft:ore_drops"},
    "copy_name": {"source": "block_entity"},  # CopyNameFunction
    "copy_components": {"source": "block_entity"},  # CopyComponentsFunction: include/exclude optionalFieldOf
    "copy_custom_data": {"source": "block_entity", "ops": []},  # CopyCustomDataFunction
    "copy_state": {"block": "minecraft:chest", "properties": []},  # CopyBlockState: properties fieldOf from 1.20.2
    "enchant_with_levels": {"levels": 30},  # EnchantWithLevelsFunction: options optionalFieldOf
    "enchanted_count_increase": {"enchantment": "minecraft:looting", "count": 1},  # EnchantedCountIncreaseFunction
    "fill_player_head": {"entity": "this"},  # FillPlayerHead
    # FilteredFunction: item_filter and modifier fieldOf (until 1.21.11)
    "filtered": {"item_filter": {}, "modifier": {"function": "minecraft:furnace_smelt"}},
    "limit_count": {"limit": 3},  # LimitCount
    # ModifyContainerContents: component and modifier fieldOf
    "modify_contents": {"component": "container", "modifier": [{"function": "minecraft:explosion_decay"}]},
    "reference": {"name": "a:m"},  # FunctionReference
    "sequence": {"functions": []},  # SequenceFunction
    "set_attributes": {"modifiers": []},  # SetAttributesFunction: replace optionalFieldOf
    "set_banner_pattern": {"patterns": [], "append": True},  # SetBannerPatternFunction: append fieldOf, no default
    "set_components": {"components": {}},  # SetComponentsFunction
    "set_contents": {"component": "container", "entries": []},  # SetContainerContents
    "set_count": {"count": 1},  # SetItemCountFunction: add fieldOf(..).orElse(false)
    "set_custom_data": {"tag": "{}"},  # SetCustomDataFunction
    "set_damage": {"damage": 0.5},  # SetItemDamageFunction
    "set_instrument": {"options": "#minecraft:goat_horns"},  # SetInstrumentFunction
    "set_item": {"item": "minecraft:stone"},  # SetItemFunction
    "set_loot_table": {"name": "a:t", "type": "minecraft:chest"},  # SetContainerLootTable: seed optionalFieldOf
    "set_lore": {"lore": [], "mode": "append"},  # SetLoreFunction: lore fieldOf, mode ListOperation.codec(256)
    "set_ominous_bottle_amplifier": {"amplifier": 1},  # SetOminousBottleAmplifierFunction
    "set_potion": {"id": "minecraft:water"},  # SetPotionFunction
    "set_writable_book_pages": {"pages": [], "mode": "replace_all"},  # SetWritableBookPagesFunction: codec(100)
    "set_written_book_pages": {"pages": [], "mode": "append"},  # SetWrittenBookPagesFunction: UNLIMITED_CODEC
    "toggle_tooltips": {"toggles": {}},  # ToggleTooltips
    # no field required: each optionalFieldOf / orElse (SetNameFunction's name too; SetCustomModelDataFunction
    # from 1.21.4: floats, flags, strings, colors)
    **{name: {} for name in ("set_name", "set_enchantments", "enchant_randomly", "exploration_map", "set_stew_effect",
                             "set_fireworks", "set_firework_explosion", "set_book_cover", "furnace_smelt",
                             "explosion_decay", "set_custom_model_data")},
}
_MINIMAL = {
    (1, 21, 4): _CODEC_ERA,
    # 1.20.5: SetCustomModelDataFunction.CODEC value fieldOf, LootingEnchantFunction.CODEC count
    # fieldOf, no enchanted_count_increase (set_item and modify_contents registered from 1.20.5-pre1)
    (1, 20, 5): {**{k: v for k, v in _CODEC_ERA.items() if k not in ("enchanted_count_increase", "set_custom_model_data")},
                 "set_custom_model_data": {"value": 1}, "looting_enchant": {"count": 1}},
    # 1.20.4 (codecs since 1.20.2): SetLoreFunction.CODEC replace fieldOf(..).orElse, no mode;
    # SetContainerContents.CODEC type fieldOf; SetNbtFunction/CopyNbtFunction.CODEC; no component functions
    (1, 20, 4): {**{k: _CODEC_ERA[k] for k in (
        "apply_bonus", "copy_name", "copy_state", "enchant_with_levels", "fill_player_head", "limit_count",
        "reference", "sequence", "set_attributes", "set_banner_pattern", "set_count", "set_damage", "set_instrument",
        "set_loot_table", "set_potion", "set_name", "set_enchantments", "enchant_randomly", "exploration_map",
        "set_stew_effect", "furnace_smelt", "explosion_decay")},
                 "set_lore": {"lore": []}, "set_contents": {"type": "minecraft:chest", "entries": []},
                 "set_nbt": {"tag": "{}"}, "copy_nbt": {"source": "block_entity", "ops": []},
                 "looting_enchant": {"count": 1}},
    # 1.19.4: each Serializer.deserialize; CopyBlockState's getAsJsonArray(json, "properties", null)
    # has a default
    (1, 19, 4): {"copy_state": {"block": "minecraft:chest"}, "set_lore": {"lore": []}, "set_count": {"count": 1},
                 "set_contents": {"type": "minecraft:chest", "entries": []}, "set_attributes": {"modifiers": []},
                 "set_nbt": {"tag": "{}"}, "set_name": {}, "set_banner_pattern": {"patterns": [], "append": True}},
}


def _check(function: dict, version) -> list[tuple[int, int, str]]:
    """The function as an item modifier file with "function" last, one field a line; its errors."""
    from mcfunction_parser.pack import loot
    from mcfunction_parser.pack.text import json_document
    text = "{\n" + "".join(f"  {json.dumps(k)}: {json.dumps(v)},\n" for k, v in function.items() if k != "function")
    text += f'  "function": {json.dumps(function["function"])}\n}}\n'
    problems = []
    loot.check_modifier(json_document(json.loads(text), "m.json", text), version, problems)
    return [(p.line, p.col, p.message) for p in problems]


def _messages(function: dict, version) -> list[str]:
    return [message for _, _, message in _check(function, version)]


def test_a_minimal_function_of_each_type_loads():
    for version, functions in _MINIMAL.items():
        for name, fields in functions.items():
            assert _check({"function": f"minecraft:{name}", **fields}, version) == [], (version, name)


def test_each_required_field_missing_is_an_error_at_the_function_type():
    # the fields of each minimal function above are exactly those the release's codec requires:
    # leaving any one out refuses the file, reported at the "function" string (the last line)
    for version, functions in _MINIMAL.items():
        for name, fields in functions.items():
            for left_out in fields:
                rest = {k: v for k, v in fields.items() if k != left_out}
                assert _check({**rest, "function": f"minecraft:{name}"}, version) == [
                    (len(rest) + 2, 15, f"item function 'minecraft:{name}' needs \"{left_out}\"")], (version, name)


def test_the_forms_real_packs_use_load():
    # the forms vanilla tables and real packs write: SetItemCountFunction.CODEC count a number
    # provider, add fieldOf(..).orElse; SetNameFunction.CODEC name/entity/target optionalFieldOf;
    # SetLoreFunction.CODEC with ListOperation.Insert's offset; SetStewEffectFunction.EffectEntry
    # type/duration fieldOf; SetAttributesFunction.Modifier (1.21: id a resource location)
    functions = [
        {"function": "set_count", "count": {"type": "minecraft:uniform", "min": 1, "max": 3}, "add": True},
        {"function": "minecraft:set_name", "name": {"text": "Boss"}, "entity": "this", "target": "item_name"},
        {"function": "minecraft:set_lore", "entity": "this", "lore": [{"text": "a"}, "b"], "mode": "insert",
         "offset": 1},
        {"function": "minecraft:set_stew_effect", "effects": [{"type": "minecraft:speed", "duration": 5}]},
        {"function": "minecraft:set_attributes", "replace": False, "modifiers": [
            {"id": "a:speed", "attribute": "minecraft:movement_speed", "amount": {"type": "uniform", "min": 0, "max": 1},
             "operation": "add_multiplied_base", "slot": ["mainhand", "offhand"]}]},
        {"function": "minecraft:copy_custom_data", "source": "block_entity",
         "ops": [{"source": "a", "target": "b", "op": "merge"}]},
        {"function": "minecraft:sequence", "functions": [
            {"function": "furnace_smelt"}, {"function": "set_custom_model_data", "floats": {"values": [1], "mode": "append"}}]},
    ]
    assert [problem for function in functions for problem in _check(function, (1, 21, 4))] == []
    # 1.20.5 - 1.20.6: SetAttributesFunction.Modifier name fieldOf, id (a UUID) optionalFieldOf
    old = {"function": "set_attributes", "modifiers": [{"name": "n", "attribute": "generic.max_health", "amount": 2,
                                                         "operation": "add_value", "slot": "any"}]}
    assert _check(old, (1, 20, 5)) == []


def test_fields_follow_the_release():
    # SetLoreFunction.CODEC: "mode" (ListOperation.codec) from 1.20.5; before it "replace" fieldOf(..).orElse
    assert _check({"function": "set_lore", "lore": ["a"]}, (1, 20, 4)) == []
    assert _check({"function": "set_lore", "lore": ["a"]}, (1, 21, 4)) == [(3, 15, "item function 'set_lore' needs \"mode\"")]
    # SetAttributesFunction.Modifier: "name" until 1.21, "id" (ResourceLocation fieldOf) from it
    modifier = {"attribute": "minecraft:armor", "amount": 1, "operation": "add_value", "slot": "any"}
    modifiers = {"function": "set_attributes", "modifiers": [modifier]}
    assert _messages(modifiers, (1, 20, 5)) == ["item function 'set_attributes': an entry of \"modifiers\" needs \"name\""]
    assert _messages(modifiers, (1, 21, 4)) == ["item function 'set_attributes': an entry of \"modifiers\" needs \"id\""]
    assert _check({"function": "set_attributes", "modifiers": [{**modifier, "name": "n"}]}, (1, 19, 4)) == []
    # FilteredFunction.CODEC: "modifier" fieldOf until 1.21.11, which has on_pass/on_fail optionalFieldOf
    filtered = {"function": "filtered", "item_filter": {}}
    assert _messages(filtered, (1, 21, 10)) == ["item function 'filtered' needs \"modifier\""]
    assert _check({**filtered, "on_pass": {"function": "furnace_smelt"}}, (1, 21, 11)) == []
    # SetCustomModelDataFunction.CODEC: "value" fieldOf until 1.21.4, then four optional lists
    assert _messages({"function": "set_custom_model_data"}, (1, 21, 3)) == [
        "item function 'set_custom_model_data' needs \"value\""]
    # CopyBlockState: properties optional in Serializer.deserialize (1.20.1), fieldOf in the CODEC (1.20.2)
    assert _check({"function": "copy_state", "block": "chest"}, (1, 20, 1)) == []
    assert _messages({"function": "copy_state", "block": "chest"}, (1, 20, 2)) == [
        "item function 'copy_state' needs \"properties\""]
    # SetContainerLootTable.Serializer reads "type" from 1.18 (getAsString, no default)
    assert _check({"function": "set_loot_table", "name": "a:t"}, (1, 17, 1)) == []
    assert _messages({"function": "set_loot_table", "name": "a:t"}, (1, 18, 0)) == [
        "item function 'set_loot_table' needs \"type\""]
    # before 1.14.4 nothing is checked (no source confirms those releases)
    assert _check({"function": "set_count"}, (1, 13, 0)) == []


def test_nested_entries_and_kinds_of_required_fields():
    # SetStewEffectFunction.EffectEntry: type and duration fieldOf; CopyCustomDataFunction.CopyOperation:
    # source, target, op fieldOf; SetLoreFunction.CODEC lore a list (listOf), SetComponentsFunction's
    # components a map (DataComponentPatch.CODEC), both at the function's type string
    assert _check({"function": "set_stew_effect", "effects": [{"type": "speed"}]}, (1, 21, 4)) == [
        (3, 15, "item function 'set_stew_effect': an entry of \"effects\" needs \"duration\"")]
    ops = {"function": "copy_custom_data", "source": "this", "ops": [{"source": "a", "target": "b"}]}
    assert _messages(ops, (1, 21, 4)) == ["item function 'copy_custom_data': an entry of \"ops\" needs \"op\""]
    assert _check({"function": "set_lore", "lore": "a", "mode": "append"}, (1, 21, 4)) == [
        (4, 15, "item function 'set_lore': \"lore\" must be a list")]
    assert _messages({"function": "set_components", "components": []}, (1, 21, 4)) == [
        "item function 'set_components': \"components\" must be a JSON object"]


def test_a_function_missing_a_field_leaves_its_file_out(tmp_path):
    # LootDataType decodes the whole file: one function missing a field and the table is not loaded
    text = ('{\n  "pools": [{"rolls": 1, "entries": [{"type": "item", "name": "stone",\n'
            '    "functions": [{"function": "minecraft:set_lore", "lore": ["a"]}]}]}]\n}\n')
    root = write_pack(tmp_path / "p", {"a/loot_table/x.json": text, "a/loot_table/good.json": json.dumps(GOOD),
                                       "a/item_modifier/m.json": '[{"function": "set_count"}]'})
    packs = load_packs([root], mc_version="1.21.4")
    assert sorted((e.path.rsplit("/", 1)[-1], e.line, e.col, e.message) for e in packs.errors) == [
        ("m.json", 1, 15, "item function 'set_count' needs \"count\""),
        ("x.json", 3, 32, "item function 'minecraft:set_lore' needs \"mode\"")]
    assert set(packs.loot_tables) == {"a:good"} and packs.item_modifiers == {}


# ---------------------------------------------------------------- the release each type appears in
# Each type from the release whose registration class first has it (decompiled: 1.13.2
# LootEntry.Serializer / LootFunctionManager / LootConditionManager; LootPoolEntries,
# LootItemFunctions, LootItemConditions, RandomIntGenerators and NumberProviders per snapshot 1.14.4 -
# 1.21.3, and in 1.21.7, 1.21.11 and 26.1.2), the first snapshot with it named; the smallest form of
# each that decodes (the fields REQUIRED_FIELDS and conditions' _REQUIRED ask for).
_TAG = {"type": "minecraft:tag", "name": "minecraft:music_discs", "expand": True}
_BOUNDARIES = [
    # LootPoolEntries (1.13.2's LootEntry.Serializer knows only item, loot_table and empty)
    ("entry", _TAG, (1, 14, 0)),  # 18w43a: TagEntry
    ("entry", {"type": "minecraft:dynamic", "name": "minecraft:contents"}, (1, 14, 0)),  # 18w43a: DynamicLoot
    ("entry", {"type": "minecraft:alternatives", "children": []}, (1, 14, 0)),  # 18w43a: AlternativesEntry
    ("entry", {"type": "minecraft:group", "children": []}, (1, 14, 0)),  # 18w43a: EntryGroup
    ("entry", {"type": "minecraft:sequence", "children": []}, (1, 14, 0)),  # 18w43a: SequentialEntry
    ("entry", {"type": "minecraft:slots", "slot_source": {"type": "minecraft:empty"}}, (1, 21, 11)),  # 25w44a: SlotLoot
    # LootItemFunctions (1.13.2's LootFunctionManager has none of these)
    ("function", {"function": "minecraft:set_stew_effect"}, (1, 14, 0)),  # 1.14 snapshots
    ("function", {"function": "minecraft:copy_name", "source": "block_entity"}, (1, 14, 0)),
    ("function", {"function": "minecraft:set_contents", "entries": []}, (1, 14, 0)),
    ("function", {"function": "minecraft:limit_count", "limit": 3}, (1, 14, 0)),
    ("function", {"function": "minecraft:apply_bonus", "enchantment": "minecraft:fortune",
                  "formula": "minecraft:ore_drops"}, (1, 14, 0)),
    ("function", {"function": "minecraft:set_loot_table", "name": "a:t"}, (1, 14, 0)),
    ("function", {"function": "minecraft:explosion_decay"}, (1, 14, 0)),
    ("function", {"function": "minecraft:set_lore", "lore": []}, (1, 14, 0)),
    ("function", {"function": "minecraft:fill_player_head", "entity": "this"}, (1, 14, 0)),
    ("function", {"function": "minecraft:copy_nbt", "source": "block_entity", "ops": []}, (1, 14, 0)),
    ("function", {"function": "minecraft:copy_state", "block": "minecraft:beehive"}, (1, 15, 0)),  # 19w36a: CopyBlockState
    ("function", {"function": "minecraft:set_banner_pattern", "patterns": [], "append": True},
     (1, 17, 0)),  # 20w45a: SetBannerPatternFunction
    ("function", {"function": "minecraft:set_enchantments"}, (1, 17, 0)),  # 20w46a: SetEnchantmentsFunction
    ("function", {"function": "minecraft:set_potion", "id": "minecraft:water"}, (1, 18, 0)),  # 21w39a: SetPotionFunction
    ("function", {"function": "minecraft:set_instrument", "options": "#minecraft:goat_horns"},
     (1, 19, 0)),  # 22w18a: SetInstrumentFunction
    ("function", {"function": "minecraft:reference", "name": "a:m"}, (1, 20, 0)),  # 23w14a: FunctionReference
    ("function", {"function": "minecraft:sequence", "functions": []}, (1, 20, 2)),  # 23w32a: SequenceFunction
    ("function", {"function": "minecraft:set_item", "item": "minecraft:stone"}, (1, 20, 5)),  # 1.20.5-pre1: SetItemFunction
    ("function", {"function": "minecraft:modify_contents", "component": "container",  # 1.20.5-pre1: ModifyContainerContents
                  "modifier": [{"function": "minecraft:explosion_decay"}]}, (1, 20, 5)),
    ("function", {"function": "minecraft:filtered", "item_filter": {},  # 1.20.5-pre1: FilteredFunction
                  "modifier": {"function": "minecraft:furnace_smelt"}}, (1, 20, 5)),
    ("function", {"function": "minecraft:discard"}, (1, 21, 11)),  # 25w43a: DiscardItem
    ("function", {"function": "minecraft:set_random_dyes", "number_of_dyes": 2}, (26, 1, 0)),  # 26.1 snapshot 1
    ("function", {"function": "minecraft:set_random_potion"}, (26, 1, 0)),  # 26.1 snapshot 1: SetRandomPotionFunction
    # LootItemConditions (1.13.2's LootConditionManager: random_chance, random_chance_with_looting,
    # entity_properties, killed_by_player, entity_scores)
    ("condition", {"condition": "minecraft:inverted", "term": {"condition": "minecraft:killed_by_player"}},
     (1, 14, 0)),  # 1.14 snapshots: InvertedLootItemCondition
    ("condition", {"condition": "minecraft:alternative", "terms": []}, (1, 14, 0)),  # AlternativeLootItemCondition
    ("condition", {"condition": "minecraft:survives_explosion"}, (1, 14, 0)),  # ExplosionCondition
    ("condition", {"condition": "minecraft:damage_source_properties"}, (1, 14, 0)),  # DamageSourceCondition
    ("condition", {"condition": "minecraft:time_check", "value": {"min": 0, "max": 12000}}, (1, 15, 0)),  # 19w38a: TimeCheck
    ("condition", {"condition": "minecraft:environment_attribute_check", "attribute": "minecraft:gameplay/can_start_raid",
                   "value": True}, (26, 1, 0)),  # 26.1-pre1: EnvironmentAttributeCheck
    # RandomIntGenerators (18w43a; 1.13.2's RandomValueRange reads only min/max), NumberProviders (20w46a)
    ("number", {"type": "minecraft:constant", "value": 2}, (1, 14, 0)),  # ConstantIntValue
    ("number", {"type": "minecraft:binomial", "n": 3, "p": 0.5}, (1, 14, 0)),  # BinomialDistributionGenerator
    ("number", {"type": "minecraft:score", "target": "this", "score": "s"}, (1, 17, 0)),  # 20w46a: ScoreboardValue
    ("number", {"type": "minecraft:storage", "storage": "a:s", "path": "n"}, (1, 20, 5)),  # 24w12a: StorageValue
    ("number", {"type": "minecraft:enchantment_level", "amount": 1}, (1, 21, 0)),  # 24w18a: EnchantmentLevelProvider
    ("number", {"type": "minecraft:sum", "summands": [1, 2]}, (26, 1, 0)),  # 26.1 snapshot 1: Sum
    ("number", {"type": "minecraft:environment_attribute", "attribute": "minecraft:visual/cloud_height"},
     (26, 1, 0)),  # 26.1-pre1: EnvironmentAttributeValue
]


def _release_before(version):
    from mcfunction_parser.pack.versions import RELEASE_FORMATS
    return max(v for v in RELEASE_FORMATS if v < version)


def _errors_of(kind: str, value: dict, version) -> list[tuple[str, str]]:
    """The value in the smallest file holding it (an item modifier for a function or a number, as
    set_count's count; a loot table's entry or pool condition otherwise): (severity, message) each."""
    from mcfunction_parser.pack import loot
    from mcfunction_parser.pack.text import json_document
    if kind in ("function", "number"):
        doc, check = (value if kind == "function" else {"function": "minecraft:set_count", "count": value}), \
            loot.check_modifier
    else:
        pool = {"rolls": 1, "entries": [value if kind == "entry" else {"type": "minecraft:empty"}]}
        if kind == "condition":
            pool["conditions"] = [value]
        doc, check = {"pools": [pool]}, loot.check_loot_table
    text = json.dumps(doc, indent=1)
    problems = []
    check(json_document(json.loads(text), "x.json", text), version, problems)
    return [(p.severity, p.message) for p in problems]


@pytest.mark.parametrize("kind,value,first", _BOUNDARIES,
                         ids=[f"{v.get('function', v.get('condition', v.get('type')))}" for _, v, _ in _BOUNDARIES])
def test_each_type_loads_from_the_release_that_registers_it(kind, value, first):
    from mcfunction_parser.diagnostics import ERROR
    assert _errors_of(kind, value, first) == []
    name = value.get("function", value.get("condition", value.get("type")))
    before = _errors_of(kind, value, _release_before(first))
    if kind == "condition":  # checked as predicate files are (conditions.problem)
        expected = f"unknown predicate condition type '{name}' in this release (it exists from {'.'.join(map(str, first))}"
    else:
        what = {"entry": "loot entry", "function": "item function", "number": "number provider"}[kind]
        expected = f"{what} type '{name}' does not exist in this version"
    assert len(before) == 1 and before[0][0] == ERROR and before[0][1].startswith(expected), before
