"""Item arguments, item predicates, slots and the item commands (give, clear, item, loot, if items)."""
from __future__ import annotations

import pytest

from mcfunction_parser import ast
from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.parse import parse_command

V121, V1204, V1215 = (1, 21, 0), (1, 20, 4), (1, 21, 5)


def parse(text, version=V121):
    cmd, diagnostics = parse_command(text, Loc("f", 1, 1), version)
    return cmd, [(d.col, d.message) for d in diagnostics]


def test_item_argument_with_components_and_removals():
    # ItemParser (1.20.5+): id[component=SNBT,!component]
    cmd, problems = parse("give @s minecraft:diamond_sword[damage=5,!food,custom_name='\"x\"'] 3")
    assert problems == [] and isinstance(cmd, ast.Give) and cmd.count == 3
    assert cmd.item.id == "minecraft:diamond_sword"
    assert cmd.item.components == (("minecraft:damage", 5), ("minecraft:custom_name", '"x"'))
    assert cmd.item.removed == ("minecraft:food",)


@pytest.mark.parametrize("text,col,message", [
    ("give @s stone[bogus=1]", 15, "unknown component 'minecraft:bogus'"),
    ("give @s stone[damage=1,damage=2]", 24, "component 'minecraft:damage' given twice"),
    ("give @s stone[fire_resistant={}]", 15, None),  # exists in 1.21.0 (replaced in 1.21.2)
    ("give @s stone 0", 15, "count"),
    ("item replace entity @s container.* with stone", 24, "unknown slot 'container.*'"),  # SlotArgument: one slot
    ("item replace entity @s hotbar.9 with stone", 24, "unknown slot 'hotbar.9'"),
    ("item replace entity @s weapon with stone 100", 42, "count"),  # 1..99
    ("clear @e stone", 7, "only players"),
])
def test_bad_item_input_fails_at_its_column(text, col, message):
    cmd, problems = parse(text)
    if message is None:
        assert problems == []
        return
    assert cmd is None and problems[0][0] == col and message in problems[0][1]


def test_component_existence_is_gated_by_version():
    # minecraft.wiki "Data component format": fire_resistant became damage_resistant in 1.21.2,
    # hide_tooltip gave way to tooltip_display in 1.21.5
    assert "does not exist in this version" in parse("give @s stone[fire_resistant={}]", (1, 21, 4))[1][0][1]
    assert parse("give @s stone[damage_resistant={types:'#minecraft:is_fire'}]", (1, 21, 4))[1] == []
    assert "does not exist" in parse("give @s stone[hide_tooltip={}]", V1215)[1][0][1]
    assert parse("give @s stone[tooltip_display={}]", V1215)[1] == []
    # the component types are each release's DataComponents registry (minecraft-data's protocol,
    # SlotComponentType): piercing_weapon came in 1.21.11, dye in 26.1
    assert parse("give @s stone[piercing_weapon={}]", (1, 21, 11))[1] == []
    assert "does not exist in this version" in parse("give @s stone[piercing_weapon={}]", (1, 21, 9))[1][0][1]
    assert parse("give @s stone[dye='red']", (26, 1, 0))[1] == []
    # after the newest data (26.1): an unknown component may be new, so a warning naming that data
    cmd, problems = parse("give @s stone[brand_new={}]", (26, 2, 0))
    assert cmd is not None and problems == [(15, "unknown component 'minecraft:brand_new' (not in the 26.1 "
                                                 "registry, the newest dpemu has)")]


@pytest.mark.parametrize("text,version,col,message", [
    # DataComponents: each component's value is decoded with its codec (NbtOps: any numeric tag
    # is a number, ExtraCodecs.NON_NEGATIVE_INT / POSITIVE_INT / intRange bound it)
    ("give @s diamond_sword[damage=-1]", V121, 30, "at least 0"),
    ("give @s diamond_sword[damage='x']", V121, 30, "expected an integer"),
    ("give @s diamond_sword[damage=3.5]", V121, None, None),  # Number.intValue(): 3
    ("give @s stone[max_stack_size=100]", V121, 30, "from 1 to 99"),
    ("give @s stone[max_damage=0]", V121, 26, "at least 1"),
    ("give @s stone[rarity=legendary]", V121, 22, "common, uncommon, rare, epic"),
    ("give @s stone[enchantment_glint_override=true]", V121, None, None),
    ("give @s stone[enchantment_glint_override='yes']", V121, 42, "true or false"),
    ("give @s stone[food={nutrition:4}]", V121, 20, "missing field 'saturation'"),
    ("give @s stone[food={nutrition:4,saturation:1.5f}]", V121, None, None),
    ("give @s stone[custom_data='{a:1}']", V121, None, None),  # CustomData: a compound or its SNBT
    ("give @s stone[custom_data=1]", V121, 27, "compound or its SNBT"),
    # custom_model_data: an int until 1.21.4 made it {floats, flags, strings, colors}
    ("give @s stone[custom_model_data=1]", V121, None, None),
    ("give @s stone[custom_model_data=1]", (1, 21, 4), 33, "expected a compound"),
    ("give @s stone[custom_model_data={floats:[1f]}]", (1, 21, 4), None, None),
    # text: a JSON string until 1.21.5, an SNBT text component from it
    ("give @s stone[custom_name={text:'a'}]", V121, 27, "expected a string"),
    ("give @s stone[custom_name={text:'a'}]", V1215, None, None),
    ("clear @s *[damage=x]", V121, 19, "expected an integer"),  # ComponentPredicateParser: the same codec
    ("clear @s *[damage~{durability:{min:1}}]", V121, None, None),  # a sub-predicate: its own codec
    # ItemDamagePredicate: durability and damage are MinMaxBounds.Ints (an int or {min, max})
    ("clear @s *[damage~{damage:3}]", V121, None, None),
    ("clear @s *[damage~{durability:'x'}]", V121, 19, "'durability': expected an int or {min, max}"),
    # ItemEnchantmentsPredicate: a list of EnchantmentPredicate (enchantments: a HolderSet, levels)
    ("clear @s *[enchantments~[{enchantments:'minecraft:sharpness',levels:{min:2}}]]", V121, None, None),
    ("clear @s *[enchantments~{levels:1}]", V121, 25, "expected a list [...], got a compound"),
    ("clear @s *[stored_enchantments~[{levels:'x'}]]", V121, 32, "entry 0: 'levels': expected an int or"),
    # ItemPotionsPredicate: a HolderSet of potions (an id, a #tag or a list of ids)
    ("clear @s *[potion_contents~['minecraft:healing','#minecraft:x']]", V121, None, None),
    ("clear @s *[potion_contents~5]", V121, 28, "expected an id, a #tag or a list of ids, got 5"),
    # NbtPredicate: TagParser.LENIENT_CODEC (SNBT in a string, or a compound); records: a compound
    ("clear @s *[custom_data~'{a:1b}']", V121, None, None),
    ("clear @s *[custom_data~5]", V121, 24, "expected a compound or its SNBT as a string"),
    ("clear @s *[trim~1]", V121, 17, "expected a compound"),
])
def test_component_values_are_read_by_their_codec(text, version, col, message):
    cmd, problems = parse(text, version)
    if message is None:
        assert problems == [] and cmd is not None
        return
    assert cmd is None and problems[0][0] == col and message in problems[0][1], problems


def test_older_releases_read_the_nbt_form():
    cmd, problems = parse("give @s stone{display:{Name:'\"a\"'}} 2", V1204)
    assert problems == [] and cmd.item.tag == {"display": {"Name": '"a"'}} and cmd.item.components == ()
    cmd, _ = parse("clear @s stone{a:1b} 0", V1204)
    assert cmd.item.tag == {"a": 1} and cmd.max_count == 0


def test_item_predicates():
    # ItemPredicateArgument: #tag or *, tests joined by ',' (all) and '|' (any), '!' negates, '~' sub-predicates,
    # count= / count~ the pseudo component and predicate (PSEUDO_COMPONENTS, PSEUDO_PREDICATES)
    cmd, problems = parse("clear @s #ns:t[!damage,custom_data~{a:1b}|count={min:2}] 0")
    assert problems == []
    predicate = cmd.item
    assert predicate.is_tag and predicate.id == "ns:t"
    assert predicate.tests[0] == (ast.ComponentTest("minecraft:damage", "exists", None, True),)
    assert [t.kind for t in predicate.tests[1]] == ["~", "="]
    assert predicate.tests[1][1].value == {"min": 2}  # count: the pseudo component, MinMaxBounds.Ints
    assert parse("clear @s *")[0].item.id is None
    assert "unknown item sub-predicate" in parse("clear @s *[food~{}]")[1][0][1]


def test_item_ids_are_checked_against_the_registry():
    # ItemParser.readItem / ItemPredicateArgument.forElementType: an unknown item fails the command
    assert parse("give @s mymod:thing")[1] == [(9, "unknown item 'mymod:thing'")]
    assert parse("clear @s diamondd")[1] == [(10, "unknown item 'minecraft:diamondd'")]
    assert parse("clear @s #mymod:things")[1] == []  # tags are the packs' to define


def test_slot_ranges_only_where_the_version_has_them():
    # SlotsArgument (execute if items, 1.20.5+) takes ranges; SlotRanges ids: armor.* is head..feet, body
    cmd, problems = parse("execute if items entity @s armor.* * run say x")
    condition = cmd.subcommands[0]
    assert problems == [] and condition.slots == ast.SlotArgument("armor.*", (103, 102, 101, 100, 105))
    assert parse("item replace entity @s player.cursor with stone")[0].slot.ids == (499,)
    assert "unknown slot" in parse("item replace entity @s horse.armor with stone")[1][0][1]
    assert parse("item replace entity @s horse.armor with stone", (1, 20, 4))[1] == []


def test_item_and_loot_command_forms():
    cmd, _ = parse("item replace block ~ ~ ~ container.0 from entity @s hotbar.2 ns:mod")
    assert (cmd.source.kind, cmd.source_slot.ids, cmd.modifier.id) == ("entity", (2,), "ns:mod")
    cmd, _ = parse('item modify entity @s armor.head {function:"set_count",count:2}')
    assert cmd.modifier.inline == {"function": "set_count", "count": 2}
    cmd, _ = parse("loot replace block 1 2 3 container.0 2 mine ~ ~ ~ mainhand")
    assert (cmd.action, cmd.count, cmd.source, cmd.tool) == ("replace", 2, "mine", "mainhand")
    cmd, _ = parse("loot insert 0 0 0 fish ns:f ~ ~ ~ stick")
    assert cmd.table.id == "ns:f" and cmd.tool.id == "minecraft:stick"
    cmd, _ = parse("loot spawn ~ ~ ~ kill @e[limit=1]")
    assert cmd.source == "kill" and cmd.entity is not None
    assert "only one entity" in parse("loot spawn ~ ~ ~ kill @e")[1][0][1]
