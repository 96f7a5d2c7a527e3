"""Putting an enchantment on an item stack as the ``enchant`` command does, with the enchantment
definitions the packs give (``data/<ns>/enchantment``, 1.21+, loaded by
:mod:`mcfunction_parser.pack.enchantments`).

- ``definition(resources, enchantment_id)``: the definition's JSON. The game's own enchantments
  are not read from the game's files here: one no pack redefines is not modelled (Unmodelled).
- ``can_enchant(resources, definition, stack)``: Enchantment.canEnchant: the stack's item is among
  ``supported_items`` (an id, a list or an item tag).
- ``compatible(resources, current, enchantment_id, definition)``: EnchantmentHelper.
  isEnchantmentCompatible: no enchantment on the stack is the same one, lists it in its
  ``exclusive_set`` or is listed in the new one's.
- ``enchant(stack, enchantment_id, level, version)``: ItemStack.enchant (ItemEnchantments.Mutable.
  upgrade: the higher of the two levels), into ``stored_enchantments`` for an enchanted book.

What an enchantment's ``effects`` do is not modelled (beyond the vanilla Unbreaking the tools and
armour carry out): putting one with effects on an item is reported as not modelled.

Sources: decompiled 1.21 server/commands/EnchantCommand.java, world/item/enchantment/Enchantment.java
(canEnchant, areCompatible, getMaxLevel), EnchantmentHelper.java (isEnchantmentCompatible,
updateEnchantments, getComponentType), ItemEnchantments.java (Mutable.upgrade).
"""
from __future__ import annotations

from emulator.world.errors import CommandFailure, Unmodelled
from emulator.world.items import ItemStack, enchantment_levels, set_component
from mcfunction_parser.nbt import Compound, Int

_FLAT_COMPONENT = (1, 21, 5)  # the enchantments component is the bare map of levels from 1.21.5


def _id(name: str) -> str:
    return name if ":" in name else "minecraft:" + name


def definition(resources, enchantment_id: str) -> dict:
    found = resources.enchantments.get(enchantment_id)
    if found is not None:
        return found
    if enchantment_id.startswith("minecraft:"):
        raise Unmodelled(f"the game's own enchantment {enchantment_id} (its definition is not read here)")
    raise CommandFailure("argument.resource.not_found", enchantment_id, "minecraft:enchantment", report=True)


def _holder_set(resources, value, registry: str) -> tuple[frozenset[str], bool]:
    """RegistryCodecs.homogeneousList's members: (ids, whether it was a tag)."""
    if isinstance(value, str) and value.startswith("#"):
        tag_id = _id(value[1:])
        if registry == "item":
            return resources.item_tag(tag_id), True
        return resources.tag_members(registry, tag_id), True
    names = [value] if isinstance(value, str) else list(value or ())
    return frozenset(_id(n) for n in names), False


def can_enchant(resources, found: dict, stack: ItemStack) -> bool:
    items, _ = _holder_set(resources, found.get("supported_items"), "item")
    return stack.id in items


def _exclusive(resources, found: dict) -> frozenset[str]:
    return _holder_set(resources, found.get("exclusive_set", []), "enchantment")[0]


def compatible(resources, current, enchantment_id: str, found: dict) -> bool:
    """Enchantment.areCompatible with each enchantment already on the stack."""
    own = _exclusive(resources, found)
    for other in current:
        if other == enchantment_id or other in own:
            return False
        if enchantment_id in _exclusive(resources, definition(resources, other)):
            return False
    return True


def component_key(stack: ItemStack) -> str:
    """EnchantmentHelper.getComponentType: an enchanted book keeps its enchantments stored."""
    return "minecraft:stored_enchantments" if stack.id == "minecraft:enchanted_book" else "minecraft:enchantments"


def current(stack: ItemStack) -> Compound:
    """EnchantmentHelper.getEnchantmentsForCrafting: the levels the stack carries (stored on a book)."""
    return enchantment_levels(stack, component_key(stack))


def enchant(stack: ItemStack, enchantment_id: str, level: int, version) -> None:
    """ItemStack.enchant: the enchantment at the higher of its levels."""
    levels = current(stack)
    if level > 0:
        levels[enchantment_id] = Int(max(level, int(levels.get(enchantment_id, 0))))
    if tuple(version) >= _FLAT_COMPONENT:
        set_component(stack, component_key(stack), levels)
        return
    before = stack.component(component_key(stack))  # keeps show_in_tooltip
    value = Compound(before) if isinstance(before, Compound) else Compound()
    value["levels"] = levels
    set_component(stack, component_key(stack), value)
