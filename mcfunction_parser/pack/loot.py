"""Checking loot tables and item modifiers as the game decodes them: the entry, function, condition
and number provider types, the shape of pools and entries. Each problem is a diagnostic at the
string it is about (its line and column in the file).

- ``check_loot_table(doc, version, diagnostics)`` / ``check_modifier(...)``: True when the file
  would load (no error found). The game refuses a file that does not decode, so the loader keeps
  only those that pass.
- ``ENTRY_TYPES``, ``FUNCTION_TYPES``, ``NUMBER_TYPES``: type name -> (first release, first
  release without it). Conditions are checked as predicate files are
  (:func:`mcfunction_parser.pack.conditions.problem`: types per release, required fields).
- ``REQUIRED_FIELDS``: the fields an item function's codec requires, per release (from 1.14.4).

Sources: the types each release registers (see the tables: the registration classes decompiled
per snapshot and release, 1.13.2 - 26.1.2); required fields from each function's
class decompiled (Mojang mappings) in every release 1.14.4 - 1.21.3, 1.21.7, 1.21.11 (FilteredFunction)
and 26.1.2 (Serializer.deserialize before 1.20.2, the CODEC from it), the releases between dated by
SpyglassMC vanilla-mcdoc's loot/function.mcdoc (filtered's ``modifier`` gone in 25w43a, 1.21.11;
set_custom_model_data's ``value`` in 24w45a, 1.21.4).
"""
from __future__ import annotations

from typing import Any

from mcfunction_parser import gamedata
from mcfunction_parser.diagnostics import ERROR, WARNING, Diagnostic
from mcfunction_parser.items import component_problem
from mcfunction_parser.pack import conditions as predicate_files
from mcfunction_parser.pack.text import JsonDocument

Version = tuple[int, int, int]
_ALWAYS = ((1, 13, 0), None)
_COMPONENTS = ((1, 20, 5), None)
_V121 = ((1, 21, 0), None)


def _table(names: str, span=_ALWAYS) -> dict[str, tuple[Version, Version | None]]:
    return {f"minecraft:{name}": span for name in names.split()}


def _since(release: Version) -> tuple[Version, None]:
    return release, None


# Each span from the release's registration class, decompiled: 1.13.2 LootEntry.Serializer /
# LootFunctionManager / LootConditionManager (MCP names); 1.14.4 - 1.21.3 LootPoolEntries,
# LootItemFunctions, LootItemConditions, RandomIntGenerators (until 1.17) and NumberProviders, snapshot
# by snapshot (MinecraftDeobfuscated-Mojang) and again per release (extracted_minecraft_data, to
# 1.21.4); then 1.21.7, 25w45a, 1.21.11 and 26.1.2. The snapshot named is the first registering the
# type: from the per-snapshot code up to 1.21.3, and as SpyglassMC vanilla-mcdoc dates it after (the
# code of 1.21.7, 1.21.11 and 26.1.2 bounding the release). 1.14's types are in the first 1.14
# snapshot, 18w43a, or soon after (misode's 18w43a notes), none in 1.13.2.
ENTRY_TYPES = {
    **_table("item loot_table empty"),  # 1.13: LootEntry.Serializer's three names
    # 1.14 (the 18w43a loot rework): LootPoolEntries, the tag and composite entries
    **_table("tag dynamic alternatives group sequence", _since((1, 14, 0))),
    **_table("slots", _since((1, 21, 11))),  # 25w44a: LootPoolEntries.SLOTS (SlotLoot)
}
FUNCTION_TYPES = {
    # 1.13: LootFunctionManager
    **_table("set_count enchant_with_levels enchant_randomly furnace_smelt set_damage set_attributes set_name "
             "exploration_map"),
    **_table("set_nbt", ((1, 13, 0), (1, 20, 5))),  # 24w09a: set_custom_data/set_components in its place
    **_table("looting_enchant", ((1, 13, 0), (1, 21, 0))),  # 24w18a: enchanted_count_increase in its place
    # 1.14 snapshots: LootItemFunctions
    **_table("set_stew_effect copy_name set_contents limit_count apply_bonus set_loot_table explosion_decay "
             "set_lore fill_player_head", _since((1, 14, 0))),
    **_table("copy_nbt", ((1, 14, 0), (1, 20, 5))),  # 24w09a: copy_custom_data/copy_components in its place
    **_table("copy_state", _since((1, 15, 0))),  # 19w36a
    **_table("set_banner_pattern set_enchantments", _since((1, 17, 0))),  # 20w45a, 20w46a
    **_table("set_potion", _since((1, 18, 0))),  # 21w39a
    **_table("set_instrument", _since((1, 19, 0))),  # 22w18a (22w17a's set_goat_horn_sound renamed)
    **_table("reference", _since((1, 20, 0))),  # 23w14a: FunctionReference
    **_table("sequence", _since((1, 20, 2))),  # 23w32a: SequenceFunction
    # 24w09a - 24w13a; filtered, set_item, modify_contents and set_custom_model_data in 1.20.5-pre1
    **_table("set_custom_data set_components copy_components copy_custom_data toggle_tooltips "
             "set_fireworks set_firework_explosion set_book_cover set_written_book_pages "
             "set_writable_book_pages set_custom_model_data set_ominous_bottle_amplifier "
             "filtered set_item modify_contents", _COMPONENTS),
    **_table("enchanted_count_increase", _V121),  # 24w18a
    **_table("discard", _since((1, 21, 11))),  # 25w43a: DiscardItem
    **_table("set_random_dyes set_random_potion", _since((26, 1, 0))),  # 26.1 snapshot 1
}
# the condition types as predicate files have them (one table: conditions.CONDITION_TYPES)
CONDITION_TYPES = {f"minecraft:{name}": span for name, span in predicate_files.CONDITION_TYPES.items()}
# 1.13's RandomValueRange reads only "min"/"max" (a "type" is ignored, so a uniform form loads);
# 18w43a (1.14) RandomIntGenerators: uniform, binomial, constant; NumberProviders from 20w46a (1.17)
NUMBER_TYPES = {
    **_table("uniform"),
    **_table("constant binomial", _since((1, 14, 0))),
    **_table("score", _since((1, 17, 0))),  # 20w46a
    **_table("storage", _COMPONENTS),  # 24w12a: StorageValue
    **_table("enchantment_level", _V121),  # 24w18a
    **_table("sum", _since((26, 1, 0))),  # 26.1 snapshot 1
    **_table("environment_attribute", _since((26, 1, 0))),  # 26.1-pre1
}
# the fields of a function that hold a number provider, or another item modifier
_NUMBER_FIELDS = {f"minecraft:{k}": v for k, v in {
    "set_count": ("count",), "set_damage": ("damage",), "enchant_with_levels": ("levels",),
    "enchanted_count_increase": ("count",), "looting_enchant": ("count",),
    "set_ominous_bottle_amplifier": ("amplifier",)}.items()}
_MODIFIER_FIELDS = {"minecraft:filtered": ("modifier", "on_pass", "on_fail")}
_CHECKED_FROM = (1, 14, 4)  # the oldest release whose source confirms the fields below


def _fields(spec: str) -> tuple[tuple[str, str, Version, Version | None], ...]:
    """``"lore[] mode@1.20.5"`` -> (field, "[]" a list / "{}" an object / "" any, first release,
    first release without it) each; ``@FROM-UNTIL`` (either may be left out) bounds the releases."""
    def release(text: str, default):
        return tuple((list(map(int, text.split("."))) + [0, 0])[:3]) if text else default
    found = []
    for word in spec.split():
        word, _, span = word.partition("@")
        first, _, until = span.partition("-")
        shape = word[-2:] if word[-2:] in ("[]", "{}") else ""
        found.append((word.removesuffix(shape), shape, release(first, _CHECKED_FROM), release(until, None)))
    return tuple(found)


# The fields an item function's codec requires, a missing one refusing the file: from 1.20.2 the
# function's CODEC (RecordCodecBuilder ``fieldOf``, not ``optionalFieldOf`` / ``strictOptionalField``
# / ``fieldOf(..).orElse``; ``mode`` is ListOperation.codec's ``dispatchMap("mode")``); 1.14.4 -
# 1.20.1 its Serializer.deserialize (``GsonHelper.getAsX(json, "name")`` with no default; set_count's
# and enchant_with_levels' ``json.get(..)`` throw without it before 1.17). Not listed, as no release
# requires a field of them: set_name (``name`` is optional), set_enchantments, enchant_randomly,
# exploration_map, set_stew_effect, set_fireworks, set_firework_explosion, set_book_cover,
# set_random_potion, furnace_smelt, explosion_decay, discard.
REQUIRED_FIELDS = {f"minecraft:{k}": _fields(v) for k, v in {
    "apply_bonus": "enchantment formula", "copy_name": "source", "copy_components": "source",
    "copy_nbt": "source ops[]", "copy_custom_data": "source ops[]", "copy_state": "block properties[]@1.20.2",
    "enchant_with_levels": "levels", "enchanted_count_increase": "enchantment count", "looting_enchant": "count",
    "fill_player_head": "entity", "filtered": "item_filter modifier@1.20.5-1.21.11", "limit_count": "limit",
    "modify_contents": "component modifier", "reference": "name", "sequence": "functions",
    "set_attributes": "modifiers[]", "set_banner_pattern": "patterns[] append", "set_components": "components{}",
    "set_contents": "entries[] type@1.18-1.20.5 component@1.20.5", "set_count": "count", "set_damage": "damage",
    "set_custom_data": "tag", "set_nbt": "tag", "set_custom_model_data": "value@-1.21.4", "set_instrument": "options",
    "set_item": "item", "set_loot_table": "name type@1.18", "set_lore": "lore[] mode@1.20.5",
    "set_ominous_bottle_amplifier": "amplifier", "set_potion": "id", "set_random_dyes": "number_of_dyes",
    "set_writable_book_pages": "pages[] mode", "set_written_book_pages": "pages[] mode", "toggle_tooltips": "toggles{}",
}.items()}
# the same for each object of a list field: SetAttributesFunction.Modifier (``name`` until 1.21, a
# ``id`` from it), SetStewEffectFunction.EffectEntry, CopyNbtFunction/CopyCustomDataFunction.CopyOperation
_ELEMENT_FIELDS = {(f"minecraft:{k}", key): _fields(v) for (k, key), v in {
    ("set_attributes", "modifiers"): "attribute operation amount slot name@-1.21 id@1.21",
    ("set_stew_effect", "effects"): "type duration",
    ("copy_nbt", "ops"): "source target op", ("copy_custom_data", "ops"): "source target op",
}.items()}


def known(table: dict, name: str, version: Version) -> bool:
    span = table.get(name)
    return span is not None and span[0] <= version and (span[1] is None or version < span[1])


def _typed(value: str) -> str:
    return value if ":" in value else "minecraft:" + value


class _Checker:
    def __init__(self, doc: JsonDocument, version: Version, diagnostics: list[Diagnostic]) -> None:
        self.doc, self.version, self.diagnostics = doc, version, diagnostics
        self.cursor = -1
        self.ok = True

    def report(self, severity: str, message: str, token: str | None) -> None:
        offset = self.doc.find_string(token, self.cursor) if token is not None else -1
        if offset >= 0:
            self.cursor = offset
        self.diagnostics.append(self.doc.diagnostic(severity, message, offset if offset >= 0 else self.cursor))
        self.ok = self.ok and severity != ERROR

    def advance(self, token: str) -> None:
        offset = self.doc.find_string(token, self.cursor)
        if offset >= 0:
            self.cursor = offset

    def type_of(self, node: dict, key: str, table: dict, what: str) -> str | None:
        raw = node.get(key)
        if not isinstance(raw, str):
            self.report(ERROR, f'{what}: expected "{key}" naming its type', key)
            return None
        name = _typed(raw)
        self.advance(raw)
        if name not in table:
            self.report(ERROR, f"unknown {what} type '{raw}'", raw)
            return None
        if not known(table, name, self.version):
            self.report(ERROR, f"{what} type '{raw}' does not exist in this version", raw)
            return None
        return name

    # ------------------------------------------------------------------ parts
    def table(self, root: Any) -> None:
        if not isinstance(root, dict):
            self.report(ERROR, "a loot table must be a JSON object", None)
            return
        pools = root.get("pools", [])
        if not isinstance(pools, list):
            self.report(ERROR, '"pools" must be a list', "pools")
            return
        for pool in pools:
            self.pool(pool)
        self.functions(root.get("functions", []))

    def pool(self, pool: Any) -> None:
        if not isinstance(pool, dict):
            self.report(ERROR, "a pool must be a JSON object", "pools")
            return
        if "rolls" not in pool:
            self.report(ERROR, 'a pool needs "rolls"', "pools")
        else:
            self.number(pool["rolls"])
        if "bonus_rolls" in pool:
            self.number(pool["bonus_rolls"])
        self.conditions(pool.get("conditions", []))
        self.functions(pool.get("functions", []))
        entries = pool.get("entries")
        if not isinstance(entries, list):
            self.report(ERROR, 'a pool needs an "entries" list', "entries")
            return
        for entry in entries:
            self.entry(entry)

    def entry(self, entry: Any) -> None:
        if not isinstance(entry, dict):
            self.report(ERROR, "an entry must be a JSON object", "entries")
            return
        kind = self.type_of(entry, "type", ENTRY_TYPES, "loot entry")
        self.conditions(entry.get("conditions", []))
        if kind in ("minecraft:item", "minecraft:tag", "minecraft:dynamic") and not isinstance(entry.get("name"), str):
            self.report(ERROR, f"a {kind.split(':')[1]} entry needs a \"name\"", kind.split(":")[1])
        elif kind == "minecraft:item":
            self.item(entry["name"])
        if kind == "minecraft:loot_table" and not isinstance(entry.get("value", entry.get("name")), (str, dict)):
            self.report(ERROR, 'a loot_table entry needs a "value"', "loot_table")
        if kind == "minecraft:loot_table" and isinstance(entry.get("value"), dict):
            self.table(entry["value"])
        if kind in ("minecraft:alternatives", "minecraft:group", "minecraft:sequence"):
            children = entry.get("children", [])
            if not isinstance(children, list):
                self.report(ERROR, '"children" must be a list', "children")
            else:
                for child in children:
                    self.entry(child)
        self.functions(entry.get("functions", []))

    def functions(self, functions: Any) -> None:
        if not isinstance(functions, list):
            self.report(ERROR, '"functions" must be a list', "functions")
            return
        for function in functions:
            self.function(function)

    def function(self, function: Any) -> None:
        if isinstance(function, list):  # an inline sequence
            self.functions(function)
            return
        if not isinstance(function, dict):
            self.report(ERROR, "an item function must be a JSON object", "function")
            return
        kind = self.type_of(function, "function", FUNCTION_TYPES, "item function")
        if kind is not None:
            self.fields(kind, function)
        self.conditions(function.get("conditions", []))
        if kind == "minecraft:set_components" and isinstance(function.get("components"), dict):
            for name in function["components"]:
                self.component(name)
        if kind == "minecraft:set_item" and isinstance(function.get("item"), str):
            self.item(function["item"])
        for key in _NUMBER_FIELDS.get(kind, ()):
            if key in function:
                self.number(function[key])
        if kind == "minecraft:sequence":
            self.functions(function.get("functions", []))
        for key in _MODIFIER_FIELDS.get(kind, ()):
            if key in function:
                self.function(function[key])

    def fields(self, kind: str, function: dict) -> None:
        """The fields the function's codec requires in this release (REQUIRED_FIELDS, and those of
        each object of a list field), each problem at the function's type string."""
        what = f"item function '{function['function']}'"
        checks = [(function, REQUIRED_FIELDS.get(kind, ()), what)]
        for (name, key), spec in _ELEMENT_FIELDS.items():
            if name == kind and isinstance(function.get(key), list):
                checks += [(e, spec, f'{what}: an entry of "{key}"') for e in function[key] if isinstance(e, dict)]
        for node, spec, where in checks:
            for field, shape, first, until in spec:
                if not (first <= self.version and (until is None or self.version < until)):
                    continue
                if field not in node:
                    self.report(ERROR, f'{where} needs "{field}"', None)
                elif shape and not isinstance(node[field], list if shape == "[]" else dict):
                    kind_of = "list" if shape == "[]" else "JSON object"
                    self.report(ERROR, f'{where}: "{field}" must be a {kind_of}', None)

    def item(self, name: str) -> None:
        """An item id in the release's item registry (an error against that release's own data,
        a warning against older data)."""
        self.advance(name)
        rid = _typed(name)
        try:
            release, exact = gamedata.registry_release(self.version)
        except gamedata.GameDataMissing:
            return
        known = gamedata.registry("item", release)
        if known and rid.startswith("minecraft:") and rid[10:] not in known:
            self.report(ERROR if exact else WARNING, f"unknown item '{name}'", name)
        elif known and not rid.startswith("minecraft:"):
            self.report(ERROR if exact else WARNING, f"unknown item '{name}'", name)

    def component(self, name: str) -> None:
        plain = name.removeprefix("!")
        problem = component_problem(_typed(plain), self.version)
        if problem is not None:
            self.report(ERROR if problem[0] == "error" else WARNING, problem[1], name)

    def conditions(self, conditions: Any) -> None:
        if not isinstance(conditions, list):
            self.report(ERROR, '"conditions" must be a list', "conditions")
            return
        for condition in conditions:
            self.condition(condition)

    def condition(self, condition: Any) -> None:
        found = predicate_files.problem(condition, self.version)
        if found is not None:
            self.report(ERROR, found[0], found[1] or None)

    def number(self, value: Any) -> None:
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            return
        if not isinstance(value, dict):
            self.report(ERROR, "expected a number or a number provider", None)
            return
        if "type" not in value and ("min" in value or "max" in value):
            value = {"type": "uniform", **value}  # the old uniform shorthand
        kind = self.type_of(value, "type", NUMBER_TYPES, "number provider")
        for key in ("min", "max", "n", "p", "value"):
            if kind is not None and key in value and kind != "minecraft:constant":
                self.number(value[key])


def check_loot_table(doc: JsonDocument, version: Version, diagnostics: list[Diagnostic]) -> bool:
    checker = _Checker(doc, version, diagnostics)
    checker.table(doc.value)
    return checker.ok


def check_modifier(doc: JsonDocument, version: Version, diagnostics: list[Diagnostic]) -> bool:
    """An item modifier: one function or a list of them (an inline sequence)."""
    checker = _Checker(doc, version, diagnostics)
    checker.function(doc.value)
    return checker.ok

