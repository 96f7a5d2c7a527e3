"""Item stacks: an id, a count and a data component patch, read from and written to the NBT the
game saves, and the item predicates of commands.

Public API
- ``ItemStack(id, count=1, patch=Compound(), tag=None)``: ``patch`` is the component patch as the
  game saves it (``"minecraft:damage": 3``, a removal as ``"!minecraft:food": {}``); ``tag`` is
  the pre-1.20.5 NBT form. ``is_empty``, ``copy()``, ``component(name)`` (the patched value or the
  item's default, None when absent or removed), ``max_stack_size``, ``same_item_same_components``.
- ``create(item_argument, count)``: an :class:`mcfunction_parser.ast.ItemArgument` made into a
  stack (a component equal to the item's default leaves the patch, a removal of a component the
  item does not have is dropped: PatchedDataComponentMap.applyPatch).
- ``to_nbt(stack, version)`` / ``from_nbt(tag)``: ``{id, count, components}`` from 1.20.5,
  ``{id, Count:1b, tag}`` before (ItemStack.save / ItemStack.parse, both forms are read).
- ``matches(predicate, stack, resources)``: ItemPredicateArgument: id / ``#tag`` / ``*``, the
  component tests (``component``, ``component=value``, ``count=N|{min,max}``, ``custom_data~{...}``,
  ``damage~{...}``, ``enchantments~[...]``, ``stored_enchantments~[...]``), or the older
  ``{nbt}`` partial match of the ``tag``. A ``~`` sub-predicate
  the emulator does not model raises ``Unmodelled`` (reported), never a silent false.
- ``DEFAULTS``: the defaults modelled: ``max_stack_size`` (1, 16 or 64), ``max_damage`` and
  ``damage`` of damageable items. Other default components (lore, rarity ...) are not modelled.

Sources (decompiled 1.21, Yeet-Masta/MCP-1.21): world/item/ItemStack.java (CODEC, isSameItemSameComponents),
core/component/PatchedDataComponentMap.java, commands/arguments/item/ItemPredicateArgument.java,
advancements/critereon/ItemDamagePredicate.java, ItemCustomDataPredicate.java,
ItemEnchantmentsPredicate.java, EnchantmentPredicate.java; durabilities from
world/item/Tiers.java and ArmorMaterials.java (base durability 11/16/15/13 x multiplier).
"""
from __future__ import annotations

from dataclasses import dataclass, field

from mcfunction_parser import ast
from mcfunction_parser.nbt import Byte, Compound, Int, List, String
from emulator.world.errors import Unmodelled
from emulator.world.nbt_ops import compare_nbt, copy_tag, is_numeric, tags_equal

AIR = "minecraft:air"
COMPONENTS_VERSION = (1, 20, 5)

_TOOL_DURABILITY = {"wooden": 59, "stone": 131, "copper": 190, "iron": 250, "golden": 32, "diamond": 1561, "netherite": 2031}
_TOOLS = ("sword", "pickaxe", "axe", "shovel", "hoe")
_ARMOR_MULTIPLIER = {"leather": 5, "chainmail": 15, "iron": 15, "golden": 7, "diamond": 33, "netherite": 37}
_ARMOR_BASE = {"helmet": 11, "chestplate": 16, "leggings": 15, "boots": 13}
_OTHER_DURABILITY = {
    "bow": 384, "crossbow": 465, "trident": 250, "shears": 238, "fishing_rod": 64, "flint_and_steel": 64,
    "shield": 336, "elytra": 432, "carrot_on_a_stick": 25, "warped_fungus_on_a_stick": 100, "brush": 64,
    "mace": 500, "turtle_helmet": 275, "wolf_armor": 64,
}
# Items that stack to 16 or do not stack (besides damageable ones), by name or name suffix.
_STACK_16 = ("ender_pearl", "snowball", "egg", "bucket", "armor_stand", "honey_bottle", "written_book",
             "_sign", "_banner", "blue_egg", "brown_egg")
_STACK_1 = ("potion", "splash_potion", "lingering_potion", "_bucket", "saddle", "minecart", "_boat", "_raft",
            "_bed", "music_disc_", "totem_of_undying", "shulker_box", "cake", "enchanted_book", "writable_book",
            "_stew", "mushroom_stew", "beetroot_soup", "bundle", "spyglass", "goat_horn", "knowledge_book",
            "debug_stick", "_horse_armor", "_pattern", "ominous_trial_key")


def _max_damage(name: str) -> int | None:
    if name in _OTHER_DURABILITY:
        return _OTHER_DURABILITY[name]
    material, _, kind = name.rpartition("_")
    if kind in _TOOLS and material in _TOOL_DURABILITY:
        return _TOOL_DURABILITY[material]
    if kind in _ARMOR_BASE and material in _ARMOR_MULTIPLIER:
        return _ARMOR_BASE[kind] * _ARMOR_MULTIPLIER[material]
    return None


def defaults(item_id: str) -> Compound:
    """The item's default components that are modelled (its prototype, partly)."""
    name = item_id.split(":", 1)[-1]
    found = Compound()
    durability = _max_damage(name) if item_id.startswith("minecraft:") else None
    if durability is not None:
        found["minecraft:max_stack_size"] = Int(1)
        found["minecraft:max_damage"] = Int(durability)
        found["minecraft:damage"] = Int(0)
    elif any(name == s or (s[0] == "_" and name.endswith(s)) or (s[-1] == "_" and name.startswith(s)) for s in _STACK_1):
        found["minecraft:max_stack_size"] = Int(1)
    elif any(name == s or (s[0] == "_" and name.endswith(s)) for s in _STACK_16):
        found["minecraft:max_stack_size"] = Int(16)
    else:
        found["minecraft:max_stack_size"] = Int(64)
    return found


DEFAULTS = defaults  # the one place item defaults come from


@dataclass
class ItemStack:
    id: str
    count: int = 1
    patch: Compound = field(default_factory=Compound)
    tag: Compound | None = None  # pre-1.20.5 NBT

    @property
    def is_empty(self) -> bool:
        return self.id == AIR or self.count <= 0

    def copy(self) -> "ItemStack":
        return ItemStack(self.id, self.count, copy_tag(self.patch), copy_tag(self.tag))

    def component(self, name: str):
        if "!" + name in self.patch:
            return None
        if name in self.patch:
            return self.patch[name]
        return defaults(self.id).get(name)

    @property
    def max_stack_size(self) -> int:
        size = self.component("minecraft:max_stack_size")
        return int(size) if is_numeric(size) else 64

    def same_item_same_components(self, other: "ItemStack") -> bool:
        """ItemStack.isSameItemSameComponents (the tag in the older form)."""
        return (self.id == other.id and tags_equal(self.patch, other.patch)
                and tags_equal(self.tag or Compound(), other.tag or Compound()))

    def is_damaged(self) -> bool:
        damage = self.component("minecraft:damage")
        return is_numeric(damage) and int(damage) > 0 and self.component("minecraft:max_damage") is not None


def enchantment_levels(stack: ItemStack, key: str = "minecraft:enchantments") -> Compound:
    """The ``levels`` of the stack's enchantments component (a copy; from 1.21.5 the component is the bare map)."""
    found = stack.component(key)
    levels = found.get("levels", found) if isinstance(found, Compound) else Compound()
    return Compound((k, v) for k, v in levels.items()) if isinstance(levels, Compound) else Compound()


def enchantment_level(stack: ItemStack | None, enchantment: str) -> int:
    if stack is None:
        return 0
    return int(enchantment_levels(stack).get(enchantment if ":" in enchantment else "minecraft:" + enchantment, 0))


EMPTY = ItemStack(AIR, 0)


def set_component(stack: ItemStack, name: str, value) -> None:
    """PatchedDataComponentMap.set: a value equal to the default leaves the patch."""
    stack.patch.pop("!" + name, None)
    default = defaults(stack.id).get(name)
    if default is not None and tags_equal(default, value):
        stack.patch.pop(name, None)
    else:
        stack.patch[name] = copy_tag(value)


def remove_component(stack: ItemStack, name: str) -> None:
    """PatchedDataComponentMap.remove: a removal is kept only for a default component."""
    stack.patch.pop(name, None)
    if name in defaults(stack.id):
        stack.patch["!" + name] = Compound()


def create(item: ast.ItemArgument, count: int) -> ItemStack:
    """ItemInput.createItemStack: the item with its components applied (or its older tag)."""
    stack = ItemStack(item.id, count, tag=copy_tag(item.tag) if item.tag else None)
    for name, value in item.components:
        set_component(stack, name, value)
    for name in item.removed:
        remove_component(stack, name)
    return stack


def to_nbt(stack: ItemStack, version) -> Compound:
    """ItemStack.save: ``{id, count, components}`` (1.20.5+) or ``{id, Count, tag}`` (older)."""
    if tuple(version) < COMPONENTS_VERSION:
        nbt = Compound(id=String(stack.id), Count=Byte(max(-128, min(127, stack.count))))
        if stack.tag:
            nbt["tag"] = copy_tag(stack.tag)
        return nbt
    nbt = Compound(id=String(stack.id), count=Int(stack.count))
    if stack.patch:
        nbt["components"] = copy_tag(stack.patch)
    return nbt


def from_nbt(tag) -> ItemStack:
    """ItemStack.parseOptional: an empty stack for anything unreadable (either save form)."""
    if not isinstance(tag, Compound) or not isinstance(tag.get("id"), str):
        return EMPTY.copy()
    item_id = str(tag["id"])
    item_id = item_id if ":" in item_id else "minecraft:" + item_id
    count = tag.get("count", tag.get("Count", Int(1)))
    components = tag.get("components")
    old = tag.get("tag")
    stack = ItemStack(item_id, int(count) if is_numeric(count) else 1,
                      copy_tag(components) if isinstance(components, Compound) else Compound(),
                      copy_tag(old) if isinstance(old, Compound) else None)
    return EMPTY.copy() if stack.is_empty else stack


# ---------------------------------------------------------------------- predicates
def matches(predicate: ast.ItemPredicate, stack: ItemStack, resources) -> bool:
    """ItemPredicateArgument's test of one stack (an empty stack matches nothing but ``air``);
    ``resources``: the world's :class:`~emulator.world.resources.Resources` (its tags)."""
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
    return all(any(_test(t, stack, resources) != t.negated for t in group) for group in predicate.tests)


def _test(test: ast.ComponentTest, stack: ItemStack, resources) -> bool:
    if test.name == "minecraft:count" and test.kind != "exists":  # MinMaxBounds.Ints: N or {min, max}
        bounds = _bounds(test.value)
        return bounds is not None and _within(bounds, stack.count)
    if test.kind == "exists":
        return stack.component(test.name) is not None
    if test.kind == "=":
        found = stack.component(test.name)
        return found is not None and value_equal(test.value, found)
    return sub_predicate(test.name, test.value, stack, resources)


def value_equal(wanted, found) -> bool:
    """Components compare as decoded values: numbers by value (``damage=3`` matches ``3`` stored
    as any numeric tag), everything else tag for tag."""
    if is_numeric(wanted) and is_numeric(found):
        return float(wanted) == float(found)
    return tags_equal(wanted, found)


def _bounds(value) -> tuple[float | None, float | None] | None:
    """MinMaxBounds as a codec reads it: a number, or ``{min, max}``."""
    if is_numeric(value):
        return float(value), float(value)
    if isinstance(value, Compound):
        lo, hi = value.get("min"), value.get("max")
        return (float(lo) if is_numeric(lo) else None), (float(hi) if is_numeric(hi) else None)
    return None


def _within(bounds, number: float) -> bool:
    lo, hi = bounds
    return (lo is None or number >= lo) and (hi is None or number <= hi)


def sub_predicate(name: str, value, stack: ItemStack, resources) -> bool:
    """ItemSubPredicate.matches: ``value`` as NBT; ``resources`` for the registry tags it names."""
    if name in ("minecraft:enchantments", "minecraft:stored_enchantments"):
        # ItemEnchantmentsPredicate: every EnchantmentPredicate of the list is in the component
        levels = enchantment_levels(stack, name)
        return isinstance(value, List) and all(
            isinstance(p, Compound) and _enchantment_in(p, levels, resources) for p in value)
    if name == "minecraft:custom_data":  # ItemCustomDataPredicate: NbtPredicate on the custom data
        return compare_nbt(value, stack.component(name) or Compound())
    if name == "minecraft:damage":  # ItemDamagePredicate: only damageable items
        max_damage = stack.component("minecraft:max_damage")
        if max_damage is None or not isinstance(value, Compound):
            return False
        damage = int(stack.component("minecraft:damage") or 0)
        for key, number in (("damage", damage), ("durability", int(max_damage) - damage)):
            if key in value:
                bounds = _bounds(value[key])
                if bounds is None or not _within(bounds, number):
                    return False
        return True
    raise Unmodelled(f"the item sub-predicate '{name}~'")


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
    if isinstance(wanted, String) and str(wanted).startswith("#"):
        tag = _namespaced(str(wanted)[1:])
        chosen = [e for e in present if resources.in_tag("enchantment", tag, e)]
    else:
        names = [wanted] if isinstance(wanted, String) else list(wanted) if isinstance(wanted, List) else []
        chosen = [e for e in map(_namespaced, map(str, names)) if e in present]
    return any(_within(bounds, present[e]) for e in chosen)


def _namespaced(name: str) -> str:
    return name if ":" in name else "minecraft:" + name
