"""Item stacks: an id, a count and a data component patch, read from and written to the NBT the
game saves (their predicates: :mod:`emulator.world.item_predicates`).

Public API
- ``ItemStack(id, count=1, patch=Compound(), tag=None)``: ``patch`` is the component patch as the
  game saves it (``"minecraft:damage": 3``, a removal as ``"!minecraft:food": {}``); ``tag`` is
  the pre-1.20.5 NBT form. ``is_empty``, ``copy()``, ``component(name)`` (the patched value or the
  item's default, None when absent or removed), ``max_stack_size``, ``same_item_same_components``.
- ``create(item_argument, count)``: an :class:`mcfunction_parser.ast.ItemArgument` made into a
  stack (a component equal to the item's default leaves the patch, a removal of a component the
  item does not have is dropped: PatchedDataComponentMap.applyPatch).
- ``to_nbt(stack, version)`` / ``from_nbt(tag)``: ``{id, count, components}`` from 1.20.5,
  ``{id, Count:1b, tag}`` before (ItemStack.save / ItemStack.parse, both forms are read); read
  components are patched as ``create`` patches them.
- ``hover_name(stack, release)`` / ``item_name(item_id, named, release)``: the stack's name as text
  (ItemStack.getHoverName: its custom name, else getItemName: its ``item_name``, else the item's
  en_us name, a block item's its block's).
- ``DEFAULTS``: the defaults modelled: ``max_stack_size`` (1, 16 or 64), ``max_damage`` and
  ``damage`` of damageable items, the empty ``container`` of container blocks' items, the empty
  ``bundle_contents`` of bundles, an enchanted book's empty ``stored_enchantments``, ``writable_book_content`` of the book and quill, ``fireworks``
  of rockets (flight duration 1) and music discs' ``jukebox_playable`` song (Items' registrations).
  Other default components (lore, rarity ...) are not modelled.

Sources (decompiled 1.21, Yeet-Masta/MCP-1.21): world/item/ItemStack.java (CODEC, isSameItemSameComponents),
core/component/PatchedDataComponentMap.java, world/item/Items.java (the defaults); durabilities from
world/item/Tiers.java and ArmorMaterials.java (base durability 11/16/15/13 x multiplier).
"""
from __future__ import annotations

from dataclasses import dataclass, field

from mcfunction_parser import ast
from mcfunction_parser.nbt import Byte, Compound, Int, List, String
from emulator.world.nbt_ops import copy_tag, is_numeric, tags_equal
from emulator.world.text import plain_text
from mcfunction_parser import gamedata
from mcfunction_parser.nbt import to_snbt

AIR = "minecraft:air"
COMPONENTS_VERSION = (1, 20, 5)
# DataComponents.COMMON_ITEM_COMPONENTS besides max_stack_size: every item has them (their values
# are not modelled: only that a patch can remove them)
COMMON_COMPONENTS = frozenset(f"minecraft:{name}" for name in ("lore", "enchantments", "repair_cost",
                                                               "attribute_modifiers", "rarity"))

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
_STACK_1 = ("potion", "splash_potion", "lingering_potion", "_bucket", "saddle", "minecart", "_minecart", "_boat", "_raft",
            "_bed", "music_disc_", "totem_of_undying", "shulker_box", "cake", "enchanted_book", "writable_book",
            "_stew", "mushroom_stew", "beetroot_soup", "bundle", "spyglass", "goat_horn", "knowledge_book",
            "debug_stick", "_horse_armor", "_pattern")


def _max_damage(name: str) -> int | None:
    if name in _OTHER_DURABILITY:
        return _OTHER_DURABILITY[name]
    material, _, kind = name.rpartition("_")
    if kind in _TOOLS and material in _TOOL_DURABILITY:
        return _TOOL_DURABILITY[material]
    if kind in _ARMOR_BASE and material in _ARMOR_MULTIPLIER:
        return _ARMOR_BASE[kind] * _ARMOR_MULTIPLIER[material]
    return None


# Items: the block items registered with DataComponents.CONTAINER = ItemContainerContents.EMPTY
_CONTAINERS = frozenset(("chest trapped_chest barrel ender_chest hopper dispenser dropper crafter furnace smoker "
                         "blast_furnace brewing_stand chiseled_bookshelf campfire soul_campfire").split())


def _content_defaults(name: str) -> Compound:
    """The default contents of containers, bundles, books, rockets and music discs."""
    if name in _CONTAINERS or name.endswith("shulker_box"):
        return Compound({"minecraft:container": List()})
    if name == "bundle" or name.endswith("_bundle"):
        return Compound({"minecraft:bundle_contents": List()})
    if name == "enchanted_book":  # ItemEnchantments.EMPTY, as 1.21.5+ writes it
        return Compound({"minecraft:stored_enchantments": Compound()})
    if name == "writable_book":
        return Compound({"minecraft:writable_book_content": Compound()})
    if name == "firework_rocket":
        return Compound({"minecraft:fireworks": Compound(flight_duration=Byte(1))})
    if name.startswith("music_disc_"):  # JukeboxSongs: music_disc_<song>
        return Compound({"minecraft:jukebox_playable": Compound(song=String("minecraft:" + name[11:]))})
    return Compound()


# DeathProtection.TOTEM_OF_UNDYING (1.21.2+; the same effects in code before)
TOTEM_PROTECTION = Compound(death_effects=List([
    Compound(type=String("minecraft:clear_all_effects")),
    Compound(type=String("minecraft:apply_effects"), effects=List([
        Compound(id=String("minecraft:regeneration"), duration=Int(900), amplifier=Int(1)),
        Compound(id=String("minecraft:absorption"), duration=Int(100), amplifier=Int(1)),
        Compound(id=String("minecraft:fire_resistance"), duration=Int(800), amplifier=Int(0))])),
]))


def defaults(item_id: str) -> Compound:
    """The item's default components that are modelled (its prototype, partly)."""
    name = item_id.split(":", 1)[-1]
    found = _content_defaults(name) if item_id.startswith("minecraft:") else Compound()
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
    if item_id == "minecraft:totem_of_undying":
        found["minecraft:death_protection"] = TOTEM_PROTECTION
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
    """The ``levels`` of the stack's enchantments component by full ids (a copy; from 1.21.5 the
    component is the bare map; :func:`set_component` keeps the ids full)."""
    found = stack.component(key)
    levels = found.get("levels", found) if isinstance(found, Compound) else Compound()
    return Compound((k, v) for k, v in levels.items()) if isinstance(levels, Compound) else Compound()


def enchantment_level(stack: ItemStack | None, enchantment: str) -> int:
    if stack is None:
        return 0
    return int(enchantment_levels(stack).get(enchantment if ":" in enchantment else "minecraft:" + enchantment, 0))


EMPTY = ItemStack(AIR, 0)


def decoded(name: str, value):
    """A component's value as its codec reads it, where two written forms decode alike:
    ``jukebox_playable`` is ``{song}`` before 1.21.5 (show_in_tooltip true unless said) and the
    song alone from 1.21.5 (JukeboxPlayable.CODEC), compared by its song; ``potion_contents`` as a
    bare potion id is ``{potion}`` (:func:`_potion_full_form`)."""
    value = _potion_full_form(name, value)
    if name == "minecraft:jukebox_playable" and isinstance(value, Compound) and "song" in value \
            and all(k == "song" or (k == "show_in_tooltip" and value[k] != 0) for k in value):
        return value["song"]
    return value


_ENCHANTMENT_MAPS = ("minecraft:enchantments", "minecraft:stored_enchantments")


def _full_ids(name: str, value):
    """The enchantment maps by their full ids, as the codec saves the holders it read
    (ItemEnchantments.CODEC: ``binding_curse`` is ``minecraft:binding_curse``), in the layout given."""
    if name not in _ENCHANTMENT_MAPS or not isinstance(value, Compound):
        return value
    levels = value.get("levels") if isinstance(value.get("levels"), Compound) else value
    if all(":" in key for key in levels):
        return value
    named = Compound((k if ":" in k else "minecraft:" + k, v) for k, v in levels.items())
    if levels is value:
        return named
    whole = Compound(value)
    whole["levels"] = named
    return whole


def _potion_full_form(name: str, value):
    """``potion_contents`` given as a bare potion id is kept as the codec saves it: ``{potion}``
    with the full id (PotionContents.CODEC encodes with FULL_CODEC), so NBT tests see that form."""
    if name != "minecraft:potion_contents" or not isinstance(value, String):
        return value
    text = str(value)
    return Compound(potion=String(text if ":" in text else "minecraft:" + text))


def set_component(stack: ItemStack, name: str, value) -> None:
    """PatchedDataComponentMap.set: a value equal to the default leaves the patch."""
    value = _potion_full_form(name, _full_ids(name, value))
    stack.patch.pop("!" + name, None)
    default = defaults(stack.id).get(name)
    if default is not None and tags_equal(decoded(name, default), decoded(name, value)):
        stack.patch.pop(name, None)
    else:
        stack.patch[name] = copy_tag(value)


def remove_component(stack: ItemStack, name: str) -> None:
    """PatchedDataComponentMap.remove: a removal is kept only for a default component (every item's
    :data:`COMMON_COMPONENTS` included)."""
    stack.patch.pop(name, None)
    if name in defaults(stack.id) or name in COMMON_COMPONENTS:
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
    """ItemStack.parseOptional: an empty stack for anything unreadable (either save form). The
    components go through the patch as the codec's stack is built (PatchedDataComponentMap.fromPatch
    -> applyPatch): a value equal to the item's default leaves it, so does a removal of a component
    the item does not have; ``damage`` is ``minecraft:damage`` (ResourceLocation)."""
    if not isinstance(tag, Compound) or not isinstance(tag.get("id"), str):
        return EMPTY.copy()
    item_id = str(tag["id"])
    item_id = item_id if ":" in item_id else "minecraft:" + item_id
    count = tag.get("count", tag.get("Count", Int(1)))
    components = tag.get("components")
    old = tag.get("tag")
    stack = ItemStack(item_id, int(count) if is_numeric(count) else 1,
                      tag=copy_tag(old) if isinstance(old, Compound) else None)
    for key, value in components.items() if isinstance(components, Compound) else ():
        removed = key.startswith("!")
        name = key[removed:] if ":" in key else "minecraft:" + key[removed:]
        if removed:
            remove_component(stack, name)
        else:
            set_component(stack, name, value)
    return EMPTY.copy() if stack.is_empty else stack


# ---------------------------------------------------------------------- names
def hover_name(stack: ItemStack, release) -> str:
    """ItemStack.getHoverName as text: its custom name (``custom_name``; ``display.Name`` before
    1.20.5), else :func:`item_name`."""
    name = stack.component("minecraft:custom_name")
    if name is None and isinstance(stack.tag, Compound) and isinstance(stack.tag.get("display"), Compound):
        name = stack.tag["display"].get("Name")
    if name is not None:
        return plain_text(str(name) if isinstance(name, str) else to_snbt(name), release)
    return item_name(stack.id, stack.component("minecraft:item_name"), release)


def item_name(item_id: str, named, release) -> str:
    """ItemStack.getItemName as text: the ``item_name`` component ``named`` (1.20.5+), else the
    item's description id in the release's en_us: ``item.<id>``, or a block item's ``block.<id>``
    (which of the two an item has is told by which key the language holds)."""
    if named is not None:
        return plain_text(str(named) if isinstance(named, str) else to_snbt(named), release)
    namespace, _, path = item_id.rpartition(":")
    key, strings = f"{namespace or 'minecraft'}.{path}", gamedata.language(tuple(release))
    return strings.get(f"item.{key}") or strings.get(f"block.{key}") or path.replace("_", " ").title()
