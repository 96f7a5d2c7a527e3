"""Item stacks, inventories and loot rolls in the world library (no backend)."""
from __future__ import annotations

import random

import pytest

from emulator.world import inventories, items, loot
from emulator.world.entities import EntityStore, entity_nbt
from emulator.world.errors import Unmodelled
from emulator.world.loot_context import LootContext
from emulator.world.resources import Resources
from emulator.world.state import WorldState
from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.items import item_argument
from mcfunction_parser.nbt import Compound, Int, String, to_snbt
from mcfunction_parser.reader import Reader

V121, V1215, V1204 = (1, 21, 0), (1, 21, 5), (1, 20, 4)


def argument(text, version=V121):
    return item_argument(Reader(text, Loc("t", 1, 1), version))


def test_patch_keeps_only_differences_from_the_defaults():
    # PatchedDataComponentMap.applyPatch: a value equal to the prototype's leaves the patch; removing
    # a component the item does not have records nothing
    stack = items.create(argument("diamond_sword[max_stack_size=1,damage=0,!custom_data,!max_damage]"), 1)
    assert stack.patch == {"!minecraft:max_damage": {}}
    assert stack.component("minecraft:max_damage") is None and stack.component("minecraft:damage") == 0
    assert items.create(argument("stone[max_stack_size=16]"), 1).max_stack_size == 16


def test_max_stack_sizes_and_durabilities():
    # Tiers / ArmorMaterials: diamond tools 1561, iron chestplate 16 x 15; ender pearls stack to 16
    assert items.defaults("minecraft:diamond_pickaxe")["minecraft:max_damage"] == 1561
    assert items.defaults("minecraft:iron_chestplate")["minecraft:max_damage"] == 240
    assert items.ItemStack("minecraft:ender_pearl").max_stack_size == 16
    assert items.ItemStack("minecraft:oak_sign").max_stack_size == 16
    assert items.ItemStack("minecraft:water_bucket").max_stack_size == 1
    assert items.ItemStack("minecraft:bucket").max_stack_size == 16
    assert items.ItemStack("minecraft:stone").max_stack_size == 64
    # Items.java (1.21): every minecart stacks to 1 (stacksTo(1)); the ominous trial key to 64 (no stacksTo)
    for cart in ("minecart", "chest_minecart", "tnt_minecart", "hopper_minecart", "command_block_minecart"):
        assert items.ItemStack("minecraft:" + cart).max_stack_size == 1
    assert items.ItemStack("minecraft:ominous_trial_key").max_stack_size == 64


def test_nbt_forms_by_version():
    # ItemStack.CODEC (1.20.5+: id, count, components) and the older {id, Count:1b, tag}
    stack = items.create(argument("stone[custom_data={a:1b}]"), 3)
    assert to_snbt(items.to_nbt(stack, V121)) == '{components:{"minecraft:custom_data":{a:1b}},count:3,id:"minecraft:stone"}'
    old = items.create(argument("stone{a:1b}", V1204), 3)
    assert to_snbt(items.to_nbt(old, V1204)) == '{Count:3b,id:"minecraft:stone",tag:{a:1b}}'
    assert items.from_nbt(items.to_nbt(stack, V121)) == stack
    assert items.from_nbt(Compound(id=String("stone"), Count=Int(2))).count == 2
    assert items.from_nbt(Compound(id=String("minecraft:air"))).is_empty


def test_read_components_are_patched_over_the_defaults():
    # ItemStack.CODEC builds the stack with PatchedDataComponentMap.fromPatch: a patch that is not
    # sanitized goes through applyPatch, so a value equal to the item's default and a removal of a
    # component the item lacks leave it; a key without namespace is minecraft's (ResourceLocation)
    read = items.from_nbt(Compound(id=String("minecraft:diamond_sword"), count=Int(1), components=Compound({
        "minecraft:damage": Int(0), "max_stack_size": Int(1), "!minecraft:food": Compound(),
        "!minecraft:max_damage": Compound(), "custom_data": Compound(a=Int(1))})))
    assert read.patch == {"!minecraft:max_damage": {}, "minecraft:custom_data": {"a": 1}}
    damaged = items.from_nbt(Compound(id=String("minecraft:diamond_sword"), components=Compound({"minecraft:damage": Int(3)})))
    assert damaged.patch == {"minecraft:damage": 3}


def _player(version_slots=None):
    store = EntityStore()
    return store.add_player("Steve", (0.0, 64.0, 0.0))


def test_inventory_add_fills_matching_stacks_then_free_slots():
    # Inventory.add / getSlotWithRemainingSpace: the selected slot, then the offhand, then slot order
    player = _player()
    player.data["SelectedItemSlot"] = Int(4)
    inv = inventories.player_inventory(player, V121)
    inventories.entity_slot(player, 4, V121).set(items.ItemStack("minecraft:stone", 60))
    inventories.entity_slot(player, 1, V121).set(items.ItemStack("minecraft:stone", 10))
    stack = items.ItemStack("minecraft:stone", 70)
    assert inv.add(stack) and stack.is_empty
    counts = {s: inventories.entity_slot(player, s, V121).get().count for s in range(4)}
    assert inventories.entity_slot(player, 4, V121).get().count == 64
    assert counts == {0: 12, 1: 64, 2: 0, 3: 0}
    assert entity_nbt(player)["SelectedItem"]["count"] == 64


def test_clear_counts_with_zero_and_removes_up_to_the_maximum():
    # ContainerHelper.clearOrCountMatchingItems: simulate counts, otherwise at most maxCount
    player = _player()
    inv = inventories.player_inventory(player, V121)
    inv.add(items.ItemStack("minecraft:stone", 100))
    full = items.ItemStack("minecraft:dirt", 64 * 40)
    # the last pass moved nothing, so Inventory.add answers false though 34 stacks went in
    assert not inv.add(full) and full.count == 64 * 6
    is_stone = lambda s: s.id == "minecraft:stone"  # noqa: E731
    assert inv.clear_or_count(is_stone, 0) == 100
    assert inv.clear_or_count(is_stone, 70) == 70
    assert inv.clear_or_count(is_stone, -1) == 30
    assert inv.clear_or_count(is_stone, 0) == 0


@pytest.mark.parametrize("version,where", [
    (V121, ("Inventory", "HandItems", "ArmorItems")), (V1215, ("Inventory", "equipment")),
])
def test_equipment_is_saved_where_the_version_saves_it(version, where):
    # 1.20.5-1.21.4: player armor in Inventory 100-103, offhand -106; mobs HandItems/ArmorItems.
    # 1.21.5: an equipment compound (minecraft.wiki "Entity format")
    store = EntityStore()
    player = store.add_player("Steve", (0.0, 64.0, 0.0))
    zombie = store.summon("minecraft:zombie", (0.0, 64.0, 0.0))
    for entity in (player, zombie):
        inventories.entity_slot(entity, inventories.ARMOR_SLOTS["head"], version).set(items.ItemStack("minecraft:iron_helmet"))
        inventories.entity_slot(entity, inventories.OFFHAND, version).set(items.ItemStack("minecraft:shield"))
    saved = {**entity_nbt(player), **entity_nbt(zombie)}
    assert all(key in saved for key in where)
    if version == V1215:
        assert entity_nbt(player)["equipment"]["head"]["id"] == "minecraft:iron_helmet"
        assert entity_nbt(zombie)["equipment"]["offhand"]["id"] == "minecraft:shield"
    else:
        assert [int(e["Slot"]) for e in entity_nbt(player)["Inventory"]] == [103, -106]
        assert entity_nbt(zombie)["ArmorItems"][3]["id"] == "minecraft:iron_helmet"
    marker = store.summon("minecraft:marker", (0.0, 0.0, 0.0))
    assert inventories.entity_slot(marker, inventories.MAINHAND, version) is None  # SlotAccess.NULL


# ---------------------------------------------------------------------- loot
def context(seed=0, version=V121, **tables):
    state = WorldState(version=version, resources=Resources(loot_tables=tables))
    return LootContext(state, random=random.Random(seed))


def roll(table, seed=0, **tables):
    return [(s.id.split(":")[1], s.count) for s in loot.roll_table(table, context(seed, **tables))]


def test_weights_pick_in_proportion():
    # LootPool.addRandomItem: nextInt(total weight), walked down the entries
    table = {"pools": [{"rolls": 1, "entries": [{"type": "item", "name": "a", "weight": 3},
                                                 {"type": "item", "name": "b", "weight": 1},
                                                 {"type": "item", "name": "c", "weight": 0}]}]}
    picks = [roll(table, seed)[0][0] for seed in range(400)]
    assert "c" not in picks and 250 < picks.count("a") < 350


def test_composite_entries():
    # AlternativesEntry: the first child whose conditions pass; SequentialEntry: children until one
    # fails; EntryGroup: all of them
    never = [{"condition": "random_chance", "chance": 0}]
    alternatives = {"type": "alternatives", "children": [{"type": "item", "name": "a", "conditions": never},
                                                          {"type": "item", "name": "b"}, {"type": "item", "name": "c"}]}
    assert roll({"pools": [{"rolls": 1, "entries": [alternatives]}]}) == [("b", 1)]
    group = {"type": "group", "children": [{"type": "item", "name": "a"}, {"type": "item", "name": "b"}]}
    assert sorted(roll({"pools": [{"rolls": 1, "entries": [group]}]}, 3)) in ([("a", 1)], [("b", 1)])
    sequence = {"type": "sequence", "children": [{"type": "item", "name": "a"}, {"type": "empty", "conditions": never},
                                                  {"type": "item", "name": "c"}]}
    assert roll({"pools": [{"rolls": 5, "entries": [sequence]}]}, 1).count(("c", 1)) == 0


def test_stacks_split_at_their_maximum_and_zero_counts_vanish():
    # LootTable.createStackSplitter; set_count of 0 drops the stack
    table = {"pools": [{"rolls": 1, "entries": [{"type": "item", "name": "ender_pearl",
                                                 "functions": [{"function": "set_count", "count": 40}]}]},
                       {"rolls": 1, "entries": [{"type": "item", "name": "stone",
                                                 "functions": [{"function": "set_count", "count": 0}]}]}]}
    assert roll(table) == [("ender_pearl", 16), ("ender_pearl", 16), ("ender_pearl", 8)]


def test_nested_tables_and_reference_cycles():
    inner = {"pools": [{"rolls": 1, "entries": [{"type": "item", "name": "apple"}]}]}
    outer = {"pools": [{"rolls": 2, "entries": [{"type": "loot_table", "value": "t:inner"}]}]}
    assert roll(outer, **{"t:inner": inner}) == [("apple", 1), ("apple", 1)]
    # LootTable.getRandomItemsRaw: a table reached again through itself is skipped ("Detected
    # infinite loop in loot tables", logged): the rest of the roll goes on
    looping = {"pools": [{"rolls": 1, "entries": [{"type": "loot_table", "value": "t:loop"}]},
                         {"rolls": 1, "entries": [{"type": "item", "name": "apple"}]}]}
    ctx = context(**{"t:loop": looping})
    outer = {"pools": [{"rolls": 1, "entries": [{"type": "loot_table", "value": "t:loop"}]}]}
    assert [s.id for s in loot.roll_table(outer, ctx)] == ["minecraft:apple"]
    assert [d.severity for d in ctx.state.diagnostics] == ["warning"]
    assert "loot_table t:loop refers back to itself" in ctx.state.diagnostics[0].message


def test_set_damage_is_a_fraction_of_durability():
    # SetItemDamageFunction: damage = floor((1 - clamp(fraction)) * max_damage)
    stack = loot.apply_modifier({"function": "set_damage", "damage": 0.25}, items.ItemStack("minecraft:iron_sword"),
                                context())
    assert stack.component("minecraft:damage") == 187  # floor(0.75 * 250)


def test_lore_modes_and_names():
    ctx = context()
    stack = items.ItemStack("minecraft:stone")
    stack = loot.apply_modifier([{"function": "set_lore", "lore": ["a", "b"]},
                                 {"function": "set_lore", "lore": ["x"], "mode": "insert", "offset": 1},
                                 {"function": "set_name", "name": {"text": "N"}}], stack, ctx)
    assert [str(line) for line in stack.component("minecraft:lore")] == ['"a"', '"x"', '"b"']
    assert stack.component("minecraft:custom_name") == '{"text":"N"}'
    # from 1.21.5 text components are stored as NBT, not JSON text
    named = loot.apply_modifier({"function": "set_name", "name": {"text": "N"}}, items.ItemStack("minecraft:stone"),
                                context(version=V1215))
    assert to_snbt(named.component("minecraft:custom_name")) == '{text:"N"}'


def test_limit_count_filtered_and_custom_data():
    ctx = context()
    stack = items.ItemStack("minecraft:stone", 50)
    stack = loot.apply_modifier([{"function": "limit_count", "limit": {"max": 10}},
                                 {"function": "filtered", "item_filter": {"items": "minecraft:dirt"},
                                  "modifier": {"function": "set_count", "count": 1}},
                                 {"function": "set_custom_data", "tag": "{a:{b:1}}"},
                                 {"function": "set_custom_data", "tag": "{a:{c:2}}"}], stack, ctx)
    assert stack.count == 10 and to_snbt(stack.component("minecraft:custom_data")) == "{a:{b:1,c:2}}"


def test_unmodelled_function_is_reported_by_name():
    # not modelled: the test meeting it is inconclusive (Unmodelled), the command fails reported
    with pytest.raises(Unmodelled) as failure:
        loot.apply_modifier({"function": "enchant_with_levels", "levels": 30}, items.ItemStack("minecraft:book"),
                            context())
    assert failure.value.report and "minecraft:enchant_with_levels" in failure.value.message
    with pytest.raises(Unmodelled, match="enchantment_active_check"):
        roll({"pools": [{"rolls": 1, "conditions": [{"condition": "enchantment_active_check", "active": True}],
                         "entries": [{"type": "item", "name": "a"}]}]})


def test_set_components_reads_custom_data_json_as_compound_tag_codec_does():
    # CustomData.CODEC: CompoundTag.CODEC converts the JSON object (DataFixerUpper JsonOps.convertTo
    # -> NbtOps: whole numbers the narrowest type, 1.0 too; an exact float a float; a byte list a
    # byte array) or TagParser reads SNBT text; another component keeps its codec's type (an int)
    table = {"pools": [{"rolls": 1, "entries": [{"type": "item", "name": "stone", "functions": [
        {"function": "set_components", "components": {
            "minecraft:custom_data": {"a": 1, "b": 1.0, "c": 300, "d": 70000, "e": 0.5, "f": 0.1, "g": True,
                                      "h": [1, 2], "i": "x"},
            "minecraft:max_stack_size": 16}}]}]}]}
    [stack] = loot.roll_table(table, context())
    assert to_snbt(stack.component("minecraft:custom_data")) == (
        '{a:1b,b:1b,c:300s,d:70000,e:0.5f,f:0.1d,g:1b,h:[B;1B,2B],i:"x"}')
    assert type(stack.component("minecraft:max_stack_size")) is Int
    text = {"pools": [{"rolls": 1, "entries": [{"type": "item", "name": "stone", "functions": [
        {"function": "set_components", "components": {"minecraft:custom_data": "{a:1}"}}]}]}]}
    [stack] = loot.roll_table(text, context())
    assert to_snbt(stack.component("minecraft:custom_data")) == "{a:1}"


def test_a_json_list_of_several_nbt_types_is_not_modelled():
    # NbtOps.createList of a byte then a short: a heterogeneous list (its form differs by release)
    table = {"pools": [{"rolls": 1, "entries": [{"type": "item", "name": "stone", "functions": [
        {"function": "set_components", "components": {"minecraft:custom_data": {"h": [1, 300]}}}]}]}]}
    with pytest.raises(Unmodelled, match="several NBT types"):
        loot.roll_table(table, context())


def test_the_same_seed_gives_the_same_loot():
    table = {"pools": [{"rolls": {"min": 1, "max": 5}, "entries": [{"type": "item", "name": "a"},
                                                                  {"type": "item", "name": "b"}]}]}
    assert roll(table, 7) == roll(table, 7)


def test_a_creative_inventory_takes_everything():
    # Inventory.add: hasInfiniteMaterials() sets the count to 0 and answers true when nothing fit
    player = _player()
    player.gamemode = "creative"
    inv = inventories.player_inventory(player, V121)
    assert inv.add(items.ItemStack("minecraft:dirt", 64 * 36))
    extra = items.ItemStack("minecraft:stone", 5)
    assert inv.add(extra) and extra.is_empty


def test_small_functions():
    # FillPlayerHeadFunction, SetOminousBottleAmplifierFunction (clamped 0-4), SetStewEffectFunction
    # (seconds x 20, ticks for instant effects), SetCustomModelDataFunction (its int form)
    ctx = context()
    ctx.this = _player()
    head = loot.apply_modifier({"function": "fill_player_head", "entity": "this"},
                               items.ItemStack("minecraft:player_head"), ctx)
    assert head.component("minecraft:profile")["name"] == "Steve"
    bottle = loot.apply_modifier({"function": "set_ominous_bottle_amplifier", "amplifier": 9},
                                 items.ItemStack("minecraft:ominous_bottle"), ctx)
    assert bottle.component("minecraft:ominous_bottle_amplifier") == 4
    stew = loot.apply_modifier({"function": "set_stew_effect", "effects": [{"type": "saturation", "duration": 7}]},
                               items.ItemStack("minecraft:suspicious_stew"), ctx)
    assert to_snbt(stew.component("minecraft:suspicious_stew_effects")) == '[{duration:7,id:"minecraft:saturation"}]'
    model = loot.apply_modifier({"function": "set_custom_model_data", "value": 3}, items.ItemStack("minecraft:stick"), ctx)
    assert model.component("minecraft:custom_model_data") == 3


def test_storage_sources_read_nbt_paths():
    # StorageValue (a number provider) and CopyCustomDataFunction from storage: an NBT path in the
    # storage; a value that is no single number reads 0
    ctx = context()
    ctx.state.storage["t:s"] = Compound(n=Int(3), deep=Compound(tag=String("x")))
    stack = loot.apply_modifier([{"function": "set_count", "count": {"type": "storage", "storage": "t:s", "path": "n"}},
                                 {"function": "copy_custom_data", "source": {"type": "storage", "source": "t:s"},
                                  "ops": [{"source": "deep.tag", "target": "copied", "op": "replace"}]}],
                                items.ItemStack("minecraft:stone"), ctx)
    assert stack.count == 3 and to_snbt(stack.component("minecraft:custom_data")) == '{copied:"x"}'
    missing = loot.apply_modifier({"function": "set_count", "count": {"type": "storage", "storage": "t:s",
                                                                       "path": "deep"}}, items.ItemStack("minecraft:stone"), ctx)
    assert missing.count == 0
