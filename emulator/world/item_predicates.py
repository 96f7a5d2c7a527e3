"""Item predicates: the command form (``id[component=value,predicate~value]``), the codec form
(the ``ItemPredicate`` of predicate files, advancements, loot conditions and of the items inside
``container~`` and ``bundle_contents~``), and every item sub-predicate (``predicates`` / ``~``).

Public API
- ``matches(predicate, stack, resources, version)``: ItemPredicateArgument's test of one stack
  (an :class:`mcfunction_parser.ast.ItemPredicate`); ``resources`` holds the registry tags.
- ``codec_matches(predicate, stack, resources, version)``: ItemPredicate.test on the predicate as
  NBT (JSON made NBT by :func:`emulator.world.loot_context.to_tag`): ``items``, ``count``,
  ``components``, ``predicates``.
- ``sub_predicate(name, value, stack, resources, version)``: one sub-predicate (ItemSubPredicate /
  DataComponentPredicate.matches) with ``value`` as NBT. A name the release does not register, or
  one the emulator does not model, raises :class:`~emulator.world.errors.Unmodelled` naming it:
  never a silent yes or no.
- ``value_equal(name, wanted, found)``: a component's exact value test.

Sources (decompiled 1.21, Yeet-Masta/MCP-1.21, advancements/critereon/): ItemPredicate.test,
ItemSubPredicates (the registered names), SingleComponentItemPredicate.matches (a stack without
the component fails), ItemDamagePredicate, ItemEnchantmentsPredicate, EnchantmentPredicate,
ItemCustomDataPredicate / NbtPredicate.matches(ItemStack), ItemPotionsPredicate,
ItemContainerPredicate (ItemContainerContents.nonEmptyItems), ItemBundlePredicate,
ItemFireworkExplosionPredicate, ItemFireworksPredicate, ItemWritableBookPredicate,
ItemWrittenBookPredicate, ItemAttributeModifiersPredicate, ItemTrimPredicate,
ItemJukeboxPlayablePredicate, CollectionPredicate / CollectionContentsPredicate /
CollectionCountsPredicate; core/component/DataComponentPredicate (exact components); the 1.21.5+
DataComponentPredicates (the same names, ``villager/variant`` added: VillagerTypePredicate).
"""
from __future__ import annotations

from typing import Callable

from mcfunction_parser import ast
from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.items import sub_predicate_registered
from mcfunction_parser.nbt import Compound, Double, Float, List
from mcfunction_parser.reader import ParseError, Reader
from mcfunction_parser.snbt import compound as parse_compound
from emulator.world.errors import CommandFailure, Unmodelled
from emulator.world.items import COMMON_COMPONENTS, ItemStack, decoded, enchantment_levels, from_nbt
from emulator.world.loot_context import component_tag, snbt_or_tag, to_tag
from emulator.world.nbt_ops import compare_nbt, is_numeric, numeric_value, tags_equal
from emulator.world.semantics import double_to_int, wrap32
from emulator.world.text import plain_value, read_component

Version = tuple[int, int, int]
TEXT_AS_SNBT: Version = (1, 21, 5)  # components hold text as SNBT, not a JSON string (25w02a)


# ---------------------------------------------------------------------- the command form
def matches(predicate: ast.ItemPredicate, stack: ItemStack, resources, version: Version) -> bool:
    """ItemPredicateArgument's test of one stack (an empty stack matches nothing but ``air``)."""
    if predicate.id is not None:
        if predicate.is_tag:
            if stack.id not in resources.item_tag(predicate.id):
                return False
        elif stack.id != predicate.id:
            return False
    elif stack.is_empty:
        return False  # '*' is any non-air item
    if predicate.tag is not None:
        return compare_nbt(predicate.tag, stack.tag)
    return all(any(_test(t, stack, resources, version) != t.negated for t in group) for group in predicate.tests)


def _test(test: ast.ComponentTest, stack: ItemStack, resources, version: Version) -> bool:
    if test.name == "minecraft:count" and test.kind != "exists":  # MinMaxBounds.Ints: N or {min, max}
        return _in_bounds(test.value, stack.count)
    if test.kind == "exists":
        return stack.component(test.name) is not None
    if test.kind == "=":
        found = stack.component(test.name)
        return found is not None and value_equal(test.name, test.value, found)
    return sub_predicate(test.name, test.value, stack, resources, version)


def value_equal(name: str, wanted, found) -> bool:
    """Components compare as decoded values (:func:`emulator.world.items.decoded`): numbers by value
    (``damage=3`` matches ``3`` stored as any numeric tag), everything else tag for tag."""
    wanted, found = decoded(name, wanted), decoded(name, found)
    if is_numeric(wanted) and is_numeric(found):
        return float(wanted) == float(found)
    return tags_equal(wanted, found)


# ---------------------------------------------------------------------- the codec form
def predicate_tag(predicate: dict) -> Compound:
    """An item predicate's JSON as NBT, each part as its codec reads it: the compound components
    and the ``custom_data`` sub-predicate as CompoundTag.CODEC converts JSON (whole numbers
    narrowed: :func:`emulator.world.loot_context.json_nbt`), the rest by ``to_tag``."""
    tag = to_tag({k: v for k, v in predicate.items() if k not in ("components", "predicates")})
    for key, convert in (("components", component_tag),
                         ("predicates", lambda name, v: snbt_or_tag(v) if name == "minecraft:custom_data" else to_tag(v))):
        part = predicate.get(key)
        if part is not None:
            tag[key] = (Compound((k, convert(_id(k), v)) for k, v in part.items()) if isinstance(part, dict)
                        else to_tag(part))
    return tag


def codec_matches(predicate: Compound, stack: ItemStack, resources, version: Version) -> bool:
    """ItemPredicate.test: ``items`` (a HolderSet of items), ``count`` (MinMaxBounds.Ints),
    ``components`` (each equal to the stack's value, DataComponentPredicate), then each of
    ``predicates``. No special case for the empty stack."""
    if not isinstance(predicate, Compound):
        return False
    if "items" in predicate and not _holders(predicate["items"], "item", stack.id, resources):
        return False
    if "count" in predicate and not _in_bounds(predicate["count"], stack.count):
        return False
    components = predicate.get("components", Compound())
    for name, value in components.items() if isinstance(components, Compound) else ():
        found = stack.component(_id(name))
        if found is None or not value_equal(_id(name), value, found):
            return False
    subs = predicate.get("predicates", Compound())
    return all(sub_predicate(_id(name), value, stack, resources, version)
               for name, value in (subs.items() if isinstance(subs, Compound) else ()))


# ---------------------------------------------------------------------- sub-predicates
def sub_predicate(name: str, value, stack: ItemStack, resources, version: Version) -> bool:
    """ItemSubPredicate.matches of ``name`` (namespaced) with its ``value`` as NBT."""
    entry = SUB_PREDICATES.get(name)
    if entry is None or not sub_predicate_registered(name, tuple(version)):
        raise Unmodelled(f"the item sub-predicate '{name}~' (not one the game registers in this release)")
    component, test = entry
    if component is None:
        return test(value, stack, resources, version)
    found = stack.component(component)
    return found is not None and test(value, found, resources, version)  # SingleComponentItemPredicate


def _damage(value, stack: ItemStack, resources, version) -> bool:
    """ItemDamagePredicate: the ``damage`` component present; ``durability`` is max damage (0 when
    the item has none) less the damage."""
    damage = stack.component("minecraft:damage")
    if damage is None or not isinstance(value, Compound):
        return False
    max_damage = stack.component("minecraft:max_damage")
    durability = (int(max_damage) if is_numeric(max_damage) else 0) - int(damage)
    return (_in_bounds(value.get("durability"), durability, True)
            and _in_bounds(value.get("damage"), int(damage), True))


def _enchantments(key: str):
    def test(value, stack: ItemStack, resources, version) -> bool:
        """ItemEnchantmentsPredicate: every EnchantmentPredicate of the list is in the component
        (every item has ``enchantments``, empty by default: DataComponents.COMMON_ITEM_COMPONENTS)."""
        if _common(stack, key) is None:
            return False
        levels = enchantment_levels(stack, key)
        return isinstance(value, List) and all(
            isinstance(p, Compound) and _enchantment_in(p, levels, resources) for p in value)
    return test


def _enchantment_in(predicate: Compound, levels: Compound, resources) -> bool:
    """EnchantmentPredicate.containedIn: with ``enchantments`` (an id, a list, or a #tag), one of
    them present at a level within ``levels``; without, any enchantment within ``levels``, or any
    enchantment at all when ``levels`` bounds nothing."""
    bounds = _bounds(predicate["levels"]) if "levels" in predicate else (None, None)
    if bounds is None:
        return False
    present = {str(k): int(v) for k, v in levels.items() if is_numeric(v) and int(v) > 0}
    wanted = predicate.get("enchantments")
    if wanted is None:
        if bounds == (None, None):
            return bool(present)
        return any(_within(bounds, level) for level in present.values())
    return any(_within(bounds, level) for e, level in present.items()
               if _holders(wanted, "enchantment", e, resources))


def _custom_data(value, stack: ItemStack, resources, version) -> bool:
    """ItemCustomDataPredicate / NbtPredicate.matches(ItemStack): the custom data (empty when
    none) partly matches the compound (given as SNBT text too: TagParser.LENIENT_CODEC)."""
    return compare_nbt(_compound(value), stack.component("minecraft:custom_data") or Compound())


def _potion_contents(value, contents, resources, version) -> bool:
    """ItemPotionsPredicate: the contents' potion (none: false) is in the HolderSet. The component
    is ``{potion: id, ...}`` or the potion's id alone."""
    potion = contents.get("potion") if isinstance(contents, Compound) else contents
    return isinstance(potion, str) and _holders(value, "potion", _id(str(potion)), resources)


def _container(value, contents, resources, version) -> bool:
    """ItemContainerPredicate: the collection predicate ``items`` over the non-empty stacks, in
    slot order (ItemContainerContents: ``[{slot, item}]``)."""
    slots = sorted((int(e["slot"]), from_nbt(e.get("item"))) for e in _list(contents)
                   if isinstance(e, Compound) and is_numeric(e.get("slot")))
    stacks = [s for _, s in slots if not s.is_empty]
    return _items_collection(value, stacks, resources, version)


def _bundle_contents(value, contents, resources, version) -> bool:
    """ItemBundlePredicate: the collection predicate ``items`` over the bundle's stacks."""
    stacks = [s for s in map(from_nbt, _list(contents)) if not s.is_empty]
    return _items_collection(value, stacks, resources, version)


def _items_collection(value, stacks: list[ItemStack], resources, version) -> bool:
    if not isinstance(value, Compound):
        return False
    return "items" not in value or _collection(
        value["items"], stacks, lambda p, s: codec_matches(p, s, resources, version))


def _firework_explosion(value, explosion, resources, version) -> bool:
    """ItemFireworkExplosionPredicate: FireworkPredicate on the explosion."""
    return _explosion_matches(value, explosion)


def _explosion_matches(predicate, explosion) -> bool:
    """FireworkPredicate.test: ``shape``, ``has_twinkle``, ``has_trail`` (FireworkExplosion:
    both false when absent)."""
    if not isinstance(predicate, Compound) or not isinstance(explosion, Compound):
        return False
    if "shape" in predicate and str(predicate["shape"]) != str(explosion.get("shape", "")):
        return False
    return all(key not in predicate or _flag(predicate[key]) == _flag(explosion.get(key))
               for key in ("has_twinkle", "has_trail"))


def _fireworks(value, fireworks, resources, version) -> bool:
    """ItemFireworksPredicate: ``explosions`` (a collection predicate of FireworkPredicate) and
    ``flight_duration`` (Fireworks: 0 when absent)."""
    if not isinstance(value, Compound) or not isinstance(fireworks, Compound):
        return False
    if "explosions" in value and not _collection(value["explosions"], _list(fireworks.get("explosions")),
                                                 _explosion_matches):
        return False
    return _in_bounds(value.get("flight_duration"), _number(fireworks.get("flight_duration")), True)


def _writable_book(value, book, resources, version) -> bool:
    """ItemWritableBookPredicate: ``pages``, a collection predicate whose elements are page texts
    equal to a page's raw text (Filterable: the text, or ``{raw, filtered}``)."""
    if not isinstance(value, Compound) or not isinstance(book, Compound):
        return False
    pages = [_raw(page) for page in _list(book.get("pages"))]
    return "pages" not in value or _collection(value["pages"], pages, lambda p, page: str(p) == str(page))


def _written_book(value, book, resources, version) -> bool:
    """ItemWrittenBookPredicate: ``author``, ``title`` (the raw title), ``generation`` (0 when
    absent), ``resolved`` (false when absent) and ``pages``: each page predicate is a text
    component equal to a page's raw text. A page is kept as a JSON string before 1.21.5
    (WrittenBookContent.CONTENT_CODEC: ComponentSerialization.flatCodec) while the predicate's page
    is read with ComponentSerialization.CODEC, where a string is plain text."""
    if not isinstance(value, Compound) or not isinstance(book, Compound):
        return False
    if "author" in value and str(value["author"]) != str(book.get("author", "")):
        return False
    if "title" in value and str(value["title"]) != str(_raw(book.get("title", ""))):
        return False
    if not _in_bounds(value.get("generation"), _number(book.get("generation")), True):
        return False
    if "resolved" in value and _flag(value["resolved"]) != _flag(book.get("resolved")):
        return False
    flat = tuple(version) < TEXT_AS_SNBT
    pages = [_text(_raw(page), flat) for page in _list(book.get("pages"))]
    return "pages" not in value or _collection(value["pages"], pages, lambda p, page: _text(p, False) == page)


def _attribute_modifiers(value, modifiers, resources, version) -> bool:
    """ItemAttributeModifiersPredicate: ``modifiers``, a collection predicate of EntryPredicate
    over the component's entries (``{modifiers: [...]}`` or the list alone; every item has the
    component, empty by default)."""
    if not isinstance(value, Compound):
        return False
    entries = modifiers.get("modifiers") if isinstance(modifiers, Compound) else modifiers
    return "modifiers" not in value or _collection(value["modifiers"], _list(entries),
                                                   lambda p, entry: _modifier_matches(p, entry, resources))


def _modifier_matches(predicate, entry, resources) -> bool:
    """EntryPredicate.test: ``attribute`` (a HolderSet), ``id``, ``amount`` (MinMaxBounds.Doubles),
    ``operation``, ``slot`` (the entry's is ``any`` when absent)."""
    if not isinstance(predicate, Compound) or not isinstance(entry, Compound):
        return False
    if "attribute" in predicate and not _holders(predicate["attribute"], "attribute",
                                                 _id(str(entry.get("type", ""))), resources):
        return False
    if "id" in predicate and _id(str(predicate["id"])) != _id(str(entry.get("id", ""))):
        return False
    if not _in_bounds(predicate.get("amount"), _number(entry.get("amount")), True, ints=False):
        return False
    if "operation" in predicate and str(predicate["operation"]) != str(entry.get("operation", "")):
        return False
    return "slot" not in predicate or str(predicate["slot"]) == str(entry.get("slot", "any"))


def _trim(value, trim, resources, version) -> bool:
    """ItemTrimPredicate: the trim's ``material`` and ``pattern`` in the HolderSets given (an
    inline definition is in no set of ids or tag)."""
    if not isinstance(value, Compound) or not isinstance(trim, Compound):
        return False
    for key, registry in (("material", "trim_material"), ("pattern", "trim_pattern")):
        if key in value and not _holders(value[key], registry, _reference(trim.get(key)), resources):
            return False
    return True


def _jukebox_playable(value, playable, resources, version) -> bool:
    """ItemJukeboxPlayablePredicate: the song's key among the ``song`` HolderSet's (an inline song
    has no key); no ``song``: true. The component is ``{song}`` or the song alone."""
    if not isinstance(value, Compound):
        return False
    song = playable.get("song") if isinstance(playable, Compound) else playable
    return "song" not in value or _holders(value["song"], "jukebox_song", _reference(song), resources)


def _villager_variant(value, variant, resources, version) -> bool:
    """VillagerTypePredicate: the variant in the HolderSet."""
    return _holders(value, "villager_type", _reference(variant), resources)


# name -> (the component it reads, None for the stack; its test); which release registers each:
# mcfunction_parser.items.sub_predicate_registered
SUB_PREDICATES: dict[str, tuple[str | None, Callable]] = {
    f"minecraft:{name}": (component and f"minecraft:{component}", test)
    for name, component, test in (
        ("damage", None, _damage),
        ("enchantments", None, _enchantments("minecraft:enchantments")),
        ("stored_enchantments", None, _enchantments("minecraft:stored_enchantments")),
        ("custom_data", None, _custom_data),
        ("potion_contents", "potion_contents", _potion_contents),
        ("container", "container", _container),
        ("bundle_contents", "bundle_contents", _bundle_contents),
        ("firework_explosion", "firework_explosion", _firework_explosion),
        ("fireworks", "fireworks", _fireworks),
        ("writable_book_content", "writable_book_content", _writable_book),
        ("written_book_content", "written_book_content", _written_book),
        ("attribute_modifiers", None, lambda v, s, r, ver: _common(s, "minecraft:attribute_modifiers") is not None
         and _attribute_modifiers(v, _common(s, "minecraft:attribute_modifiers"), r, ver)),
        ("trim", "trim", _trim),
        ("jukebox_playable", "jukebox_playable", _jukebox_playable),
        ("villager/variant", "villager/variant", _villager_variant),
    )
}


def _common(stack: ItemStack, name: str):
    """The stack's component, where every item has ``enchantments`` and ``attribute_modifiers``
    (empty by default: DataComponents.COMMON_ITEM_COMPONENTS) unless its patch removed them."""
    found = stack.component(name)
    if found is None and name in COMMON_COMPONENTS and "!" + name not in stack.patch:
        return Compound()
    return found


# ---------------------------------------------------------------------- collections
def _collection(predicate, elements: list, test: Callable) -> bool:
    """CollectionPredicate.test: ``contains`` (each listed predicate matched by some element: an
    element takes away every predicate it matches, CollectionContentsPredicate.Multiple), ``count``
    (``[{test, count}]``: how many elements match each test) and ``size``."""
    if not isinstance(predicate, Compound):
        return False
    if "contains" in predicate:
        left = list(_list(predicate["contains"]))
        for element in elements:
            left = [p for p in left if not test(p, element)]
            if not left:
                break
        if left:
            return False
    for entry in _list(predicate.get("count")):
        if not isinstance(entry, Compound) or "test" not in entry:
            return False
        if not _in_bounds(entry.get("count"), sum(1 for e in elements if test(entry["test"], e))):
            return False
    return "size" not in predicate or _in_bounds(predicate["size"], len(elements))


# ---------------------------------------------------------------------- values
def _holders(value, registry: str, member: str | None, resources) -> bool:
    """HolderSet.contains: an id, a ``#tag`` (the registry's tags) or a list of ids; ``member``
    None is an inline (direct) value, in no such set."""
    if member is None:
        return False
    if isinstance(value, List):
        return any(_id(str(v)) == member for v in value)
    text = str(value)
    if text.startswith("#"):
        return resources.in_tag(registry, _id(text[1:]), member)
    return _id(text) == member


def _reference(value) -> str | None:
    """A registry reference (an id) or None for an inline definition."""
    return _id(str(value)) if isinstance(value, str) else None


def _bounds(value, ints: bool = True) -> tuple[float | None, float | None] | None:
    """MinMaxBounds.Ints (Doubles unless ``ints``) as its codec reads NBT: a number, or ``{min, max}``."""
    if is_numeric(value):
        return _codec_number(value, ints), _codec_number(value, ints)
    if isinstance(value, Compound):
        lo, hi = value.get("min"), value.get("max")
        return (_codec_number(lo, ints) if is_numeric(lo) else None), (_codec_number(hi, ints) if is_numeric(hi) else None)
    return None


def _codec_number(tag, ints: bool) -> float:
    """Codec.INT / Codec.DOUBLE on a numeric tag (NbtOps.getNumberValue, then Number.intValue: a
    long keeps its low 32 bits, a float or double is cast, truncated toward zero and saturated)."""
    if not ints:
        return numeric_value(tag)
    if isinstance(tag, (Float, Double)):
        return double_to_int(numeric_value(tag))
    return wrap32(int(tag))


def _within(bounds, number: float) -> bool:
    lo, hi = bounds
    return (lo is None or number >= lo) and (hi is None or number <= hi)


def _in_bounds(value, number: float, absent_matches: bool = False, ints: bool = True) -> bool:
    """MinMaxBounds.matches (Ints unless ``ints`` is False); an absent field is MinMaxBounds.ANY
    when ``absent_matches``."""
    if value is None:
        return absent_matches
    bounds = _bounds(value, ints)
    return bounds is not None and _within(bounds, number)


def _list(value) -> list:
    return list(value) if isinstance(value, List) else []


def _flag(value) -> bool:
    return is_numeric(value) and numeric_value(value) != 0


def _number(value) -> float:
    return numeric_value(value) if is_numeric(value) else 0.0


def _raw(value):
    """Filterable: ``{raw, filtered}`` or the value alone."""
    return value.get("raw") if isinstance(value, Compound) and "raw" in value else value


def _text(value, flat: bool):
    """A text component as a plain value to compare (ComponentSerialization): a string is plain
    text (``flat``: a JSON string to read), a list its first part with the rest as ``extra``."""
    if flat and isinstance(value, str):
        value = read_component(str(value))
    elif isinstance(value, (Compound, List)):
        value = plain_value(value)
    elif isinstance(value, str):
        value = str(value)
    return _normal(value)


def _normal(value):
    if isinstance(value, str):
        return {"text": value}
    if isinstance(value, list):
        if not value:
            return None
        first = dict(_normal(value[0]) or {})
        first["extra"] = [_normal(v) for v in first.get("extra", [])] + [_normal(v) for v in value[1:]]
        return first
    if isinstance(value, dict):
        found = {k: v for k, v in value.items() if k != "type"}
        if "extra" in found:
            found["extra"] = [_normal(v) for v in found["extra"]]
        if not found.get("extra"):
            found.pop("extra", None)
        return found
    return value


def _compound(value) -> Compound:
    """A compound, or its SNBT as a string."""
    if isinstance(value, Compound):
        return value
    try:
        return parse_compound(Reader(str(value), Loc("<predicate>", 1, 1), (1, 21, 4)))
    except ParseError as error:
        raise CommandFailure("dpemu.loot.invalid", f"the SNBT '{value}'", error.message, report=True) from None


def _id(name: str) -> str:
    return name if ":" in name else "minecraft:" + name
