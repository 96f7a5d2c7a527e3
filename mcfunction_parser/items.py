"""Item arguments: items to create, item predicates, slot names and the data component table.

- ``item_argument(r)``: ItemArgument / ItemParser: ``id[component=value,!component,...]`` (1.20.5+)
  or ``id{tag}`` (older releases).
- ``item_predicate(r)``: ItemPredicateArgument: ``id``, ``#tag`` or ``*`` (``*`` from 1.20.5) then
  ``[test,test|test,!test]`` where a test is ``component``, ``component=value``,
  ``predicate~value`` or ``count=N`` / ``count={min,max}`` (1.20.5+), or ``{nbt}`` (older). Item
  ids are checked against the release's item registry (:func:`.game_objects.check_id`).
- ``slot(r, ranges=False)``: SlotArgument (one slot) or, with ``ranges``, SlotsArgument
  (``container.*``, ``armor.*`` ...): the name and the slot ids it stands for (SlotRanges).
- ``component_problem``: a data component id checked against the release's data component types
  (DataComponents' registry, :mod:`.gamedata`); ``SUB_PREDICATES``: the ``~`` predicates
  (ItemSubPredicates), ``sub_predicate_registered(name, version)``.

Sources (decompiled 1.21, Yeet-Masta/MCP-1.21): commands/arguments/item/ItemParser.java,
ItemPredicateArgument.java, ComponentPredicateParser.java, world/inventory/SlotRanges.java,
core/component/DataComponents.java, advancements/critereon/ItemSubPredicates.java.
"""
from __future__ import annotations

import re

from . import ast, codecs, gamedata
from .features import version_text
from .game_objects import check_id
from .primitives import resource_location
from .reader import Reader
from .snbt import compound, value

Version = tuple[int, int, int]
_COMPONENT_ID = re.compile(r"[0-9a-z_:/.\-]*")
COMPONENTS_VERSION: Version = (1, 20, 5)  # 24w09a: components replace the item's tag

# component -> the shape of its value (DataComponents: each type's codec), for the components whose
# codec is a number, a flag, an enum, a string, a list or a record with required fields; the others'
# values are read as SNBT and not checked further
VALUES: dict[str, codecs.Shape] = {f"minecraft:{name}": shape for name, shape in {
    "damage": codecs.int_at_least(0),
    "max_damage": codecs.int_at_least(1),
    "max_stack_size": codecs.int_between(1, 99),
    "repair_cost": codecs.int_at_least(0),
    "map_id": codecs.int_at_least(-2**31),
    "ominous_bottle_amplifier": codecs.int_between(0, 4),
    "enchantment_glint_override": codecs.boolean,
    "rarity": codecs.one_of("common", "uncommon", "rare", "epic"),
    "custom_data": codecs.either(codecs.compound, codecs.string, what="a compound or its SNBT as a string"),
    "custom_name": codecs.TEXT,
    "item_name": codecs.TEXT,
    "lore": codecs.a_list,
    "custom_model_data": codecs.since((1, 21, 4), codecs.compound, codecs.int_at_least(-2**31)),
    "dyed_color": codecs.since(codecs.TEXT_AS_SNBT, codecs.RGB, codecs.either(
        codecs.int_at_least(-2**31), codecs.fields(("rgb", codecs.int_at_least(-2**31))),
        what="an RGB int or {rgb: int}")),
    "map_color": codecs.int_at_least(-2**31),
    "food": codecs.fields(("nutrition", codecs.int_at_least(0)), ("saturation", codecs.number)),
    "enchantments": codecs.compound,
    "stored_enchantments": codecs.compound,
    "unbreakable": codecs.compound,
    "attribute_modifiers": codecs.since(codecs.TEXT_AS_SNBT, codecs.a_list, codecs.either(
        codecs.a_list, codecs.compound, what="a list or a compound")),
    "container": codecs.a_list,
    "bundle_contents": codecs.a_list,
    "charged_projectiles": codecs.a_list,
    "recipes": codecs.a_list,
    "trim": codecs.fields(*((key, codecs.either(codecs.string, codecs.compound, what="an id or an inline definition"))
                            for key in ("material", "pattern"))),
}.items()}
# MinMaxBounds.Ints.CODEC: Codec.either({min?, max?}, Codec.INT)
_INT_BOUNDS = codecs.either(codecs.fields(optional=(("min", codecs.int_at_least(-2**31)),
                                                    ("max", codecs.int_at_least(-2**31)))),
                            codecs.int_at_least(-2**31), what="an int or {min, max}")
# RegistryCodecs.homogeneousList: an id, a #tag, or a list of ids
_HOLDERS = codecs.either(codecs.string, codecs.list_of(codecs.string), what="an id, a #tag or a list of ids")
_ENCHANTMENTS = codecs.list_of(codecs.fields(optional=(("enchantments", _HOLDERS), ("levels", _INT_BOUNDS))))
# the ``~`` predicates (ItemSubPredicates) and the shape of each one's value: its codec (1.21
# critereon classes: ItemDamagePredicate, ItemEnchantmentsPredicate over EnchantmentPredicate,
# ItemPotionsPredicate, ItemCustomDataPredicate (NbtPredicate: TagParser.LENIENT_CODEC),
# ItemJukeboxPlayablePredicate, VillagerTypePredicate; the others are records, read from a compound)
SUB_PREDICATES: dict[str, codecs.Shape] = {f"minecraft:{name}": shape for name, shape in {
    "damage": codecs.fields(optional=(("durability", _INT_BOUNDS), ("damage", _INT_BOUNDS))),
    "enchantments": _ENCHANTMENTS,
    "stored_enchantments": _ENCHANTMENTS,
    "potion_contents": _HOLDERS,
    "custom_data": codecs.either(codecs.string, codecs.compound, what="a compound or its SNBT as a string"),
    "jukebox_playable": codecs.fields(optional=(("song", _HOLDERS),)),
    "villager/variant": _HOLDERS,
    **{name: codecs.compound for name in (
        "container bundle_contents firework_explosion fireworks writable_book_content written_book_content "
        "attribute_modifiers trim").split()},
}.items()}


# the sub-predicates registered after 1.20.5: jukebox_playable with its component (1.21); the
# 1.21.5+ DataComponentPredicates' villager/variant, found in the 1.21.11 and 26.1 sources and in no
# list up to 1.21.7 (the release between that added it is unconfirmed: read from 1.21.11)
SUB_PREDICATES_SINCE: dict[str, Version] = {"minecraft:jukebox_playable": (1, 21, 0),
                                            "minecraft:villager/variant": (1, 21, 11)}


def sub_predicate_registered(name: str, version: Version) -> bool:
    """Whether the release registers item sub-predicate ``name`` (namespaced)."""
    return name in SUB_PREDICATES and version >= SUB_PREDICATES_SINCE.get(name, COMPONENTS_VERSION)


def component_problem(name: str, version: Version) -> tuple[str, str] | None:
    """(severity, message) when ``name`` is not a data component type of ``version``: an error
    against the release's own registry, a warning against an older release's (a release after
    the newest data dpemu has may have added it)."""
    namespace, _, path = name.partition(":")
    try:
        release, exact = gamedata.registry_release(version)
    except gamedata.GameDataMissing:
        return None
    known = gamedata.registry("data_component_type", release)
    if not known or (namespace == "minecraft" and path in known):
        return None
    if not exact:
        return "warning", (f"unknown component '{name}' (not in the {version_text(release)} registry, "
                           "the newest dpemu has)")
    if namespace == "minecraft" and gamedata.in_any_release("data_component_type", path):
        return "error", f"component '{name}' does not exist in this version"
    return "error", f"unknown component '{name}'"


# ----------------------------------------------------------------------------- slots

def _slot_table() -> dict[str, tuple[tuple[int, ...], Version, Version | None]]:
    """SlotRanges: name -> (slot ids, since, until). Ranges (``.*``) and the slots added with them
    exist from 1.20.5 (24w10a); the older slot names are SlotArgument's (1.17)."""
    new = (1, 20, 5)
    table: dict = {}

    def add(name, ids, since=(1, 13, 0), until=None):
        table[name] = (tuple(ids), since, until)

    def add_range(prefix, start, size):
        for i in range(size):
            add(f"{prefix}{i}", [start + i])
        add(prefix + "*", range(start, start + size), new)

    add("contents", [0], new)
    add_range("container.", 0, 54)
    add_range("hotbar.", 0, 9)
    add_range("inventory.", 9, 27)
    add_range("enderchest.", 200, 27)
    add_range("villager.", 300, 8)
    add_range("horse.", 500, 15)
    add("weapon", [98])
    add("weapon.mainhand", [98])
    add("weapon.offhand", [99])
    add("weapon.*", [98, 99], new)
    for name, slot in (("head", 103), ("chest", 102), ("legs", 101), ("feet", 100)):
        add(f"armor.{name}", [slot])
    add("armor.body", [105], new)
    add("armor.*", [103, 102, 101, 100, 105], new)
    add("horse.saddle", [400])
    add("horse.armor", [401], until=new)
    add("horse.chest", [499])
    add("player.cursor", [499], new)
    for i in range(4):
        add(f"player.crafting.{i}", [500 + i], new)
    add("player.crafting.*", range(500, 504), new)
    add("saddle", [400], (1, 21, 5))
    return table


SLOTS = _slot_table()


def slot(r: Reader, ranges: bool = False) -> ast.SlotArgument:
    """A slot name (SlotArgument), or with ``ranges`` a slot range name (SlotsArgument)."""
    start = r.pos
    name = r.word()
    entry = SLOTS.get(name)
    if (entry is None or not entry[1] <= r.version or (entry[2] is not None and r.version >= entry[2])
            or (len(entry[0]) > 1 and not ranges) or (name.endswith(".*") and not ranges)):
        r.fail(f"unknown slot '{name}'" if name else f"expected a slot, got {r.found()}", start)
    return ast.SlotArgument.new(name, entry[0])


# ----------------------------------------------------------------------------- items

def item_argument(r: Reader) -> ast.ItemArgument:
    """``id[components]`` (1.20.5+) or ``id{tag}``; unknown or repeated components fail."""
    loc, start = r.loc(), r.pos
    item_id = resource_location(r, "item")
    check_id(r, "item", item_id, start)
    if r.version < COMPONENTS_VERSION:
        tag = compound(r) if r.peek() == "{" else None
        return ast.ItemArgument.new(loc, item_id, tag=tag)
    components: list = []
    removed: list[str] = []
    seen: set[str] = set()

    def one() -> None:
        negated = r.peek() == "!"
        if negated:
            r.pos += 1
        start = r.pos
        name = _component_id(r)
        _check_component(r, name, start)
        if name in seen:
            r.fail(f"component '{name}' given twice", start)
        seen.add(name)
        r.skip_ws()
        if negated:
            removed.append(name)
            return
        r.expect("=")
        r.skip_ws()
        components.append((name, _component_value(r, name)))

    _bracketed(r, one, "the item's components")
    return ast.ItemArgument.new(loc, item_id, tuple(components), tuple(removed))


def _component_value(r: Reader, name: str):
    """The SNBT value of component ``name``, read as its codec reads it (VALUES)."""
    start = r.pos
    tag = value(r)
    shape = VALUES.get(name)
    problem = shape(tag, r.version) if shape is not None else None
    if problem:
        r.fail(f"invalid value for component '{name}': {problem}", start)
    return tag


def _sub_predicate_value(r: Reader, name: str):
    """The SNBT value of sub-predicate ``name`` (``count~`` is the pseudo one: bounds)."""
    start = r.pos
    tag = value(r)
    shape = _INT_BOUNDS if name == "minecraft:count" else SUB_PREDICATES.get(name)
    problem = shape(tag, r.version) if shape is not None else None
    if problem:
        r.fail(f"invalid value for item sub-predicate '{name}': {problem}", start)
    return tag


def _bracketed(r: Reader, one, what: str) -> None:
    """``[one, one, ...]`` when the cursor is at ``[`` (whitespace allowed around each)."""
    if r.peek() != "[":
        return
    r.pos += 1
    r.skip_ws()
    while r.peek() != "]":
        one()
        r.skip_ws()
        if r.peek() == ",":
            r.pos += 1
            r.skip_ws()
        elif r.peek() != "]":
            r.fail(f"expected ',' or ']' in {what}, got {r.found()}")
    r.pos += 1


def _component_id(r: Reader) -> str:
    """A component id inside brackets (ends at ``= ~ , ] |`` or a space)."""
    start = r.pos
    m = _COMPONENT_ID.match(r.text, start)
    if not m.group():
        r.fail(f"expected a component, got {r.found()}")
    r.pos = m.end()
    name = m.group()
    if name.count(":") > 1:
        r.fail(f"invalid component id '{name}'", start)
    return name if ":" in name else "minecraft:" + name


def _check_component(r: Reader, name: str, start: int, sub_predicate: bool = False) -> None:
    if sub_predicate:
        if not sub_predicate_registered(name, r.version):
            r.fail(f"unknown item sub-predicate '{name}'", start)
        return
    problem = component_problem(name, r.version)
    if problem is None:
        return
    severity, message = problem
    if severity == "error":
        r.fail(message, start)
    r.warnings.append((message, start))


def item_predicate(r: Reader) -> ast.ItemPredicate:
    """``id|#tag|*`` then ``[tests]`` (1.20.5+) or ``{nbt}`` (older)."""
    loc = r.loc()
    is_tag = r.peek() == "#"
    if is_tag:
        r.pos += 1
        item_id = resource_location(r, "item tag")
    elif r.peek() == "*" and r.version >= COMPONENTS_VERSION:
        r.pos += 1
        item_id = None
    else:
        start = r.pos
        item_id = resource_location(r, "item")
        check_id(r, "item", item_id, start)
    if r.version < COMPONENTS_VERSION:
        tag = compound(r) if r.peek() == "{" else None
        return ast.ItemPredicate.new(loc, item_id, is_tag, tag=tag)
    groups: list = []
    _bracketed(r, lambda: groups.append(_any_of(r)), "the item predicate")
    return ast.ItemPredicate.new(loc, item_id, is_tag, tuple(groups))


def _any_of(r: Reader) -> tuple[ast.ComponentTest, ...]:
    tests = [_test(r)]
    r.skip_ws()
    while r.peek() == "|":
        r.pos += 1
        r.skip_ws()
        tests.append(_test(r))
        r.skip_ws()
    return tuple(tests)


def _test(r: Reader) -> ast.ComponentTest:
    negated = r.peek() == "!"
    if negated:
        r.pos += 1
    start = r.pos
    name = _component_id(r)
    r.skip_ws()
    op = r.peek()
    if op in ("=", "~"):
        if name != "minecraft:count":  # count= and count~ are pseudo ones: an int or {min, max}
            _check_component(r, name, start, sub_predicate=op == "~")
        r.pos += 1
        r.skip_ws()
        # name=value: ComponentPredicateParser reads the value with the component's own codec,
        # name~value with the sub-predicate's
        tag = _component_value(r, name) if op == "=" else _sub_predicate_value(r, name)
        return ast.ComponentTest.new(name, op, tag, negated)
    _check_component(r, name, start)
    return ast.ComponentTest.new(name, "exists", None, negated)
