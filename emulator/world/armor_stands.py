"""A player using an armor stand (ArmorStand.interactAt): the held item and the stand's slot trade
places, with what a datapack observes (the stand's equipment, the player's hand).

- ``interact_at(state, player, hand, stand, at) -> str``: ``"consume"``, ``"pass"`` or ``"fail"``.
- ``equipment_slot_for(stack)``: LivingEntity.getEquipmentSlotForItem for an armor stand (the slot
  the item is worn in, else the main hand).

The rules (ArmorStand.interactAt, 1.21.x): a marker, or a name tag in hand, passes (the name tag
then names the stand: emulator.world.mob_use.item_on_living); a spectator succeeds without a change.
With an item in hand the slot is the one the item is worn in (helmets, heads, carved pumpkins: head;
chestplates, elytra: chest; leggings; boots; a shield: offhand; else the main hand); a disabled
slot, or a hand slot on a stand without arms, fails. With an empty hand the slot is the one clicked
(getClickedSlot: the click's height over the stand's scale, 0.5 for a small stand, picks feet,
chest, legs or head when that slot holds something; else the main hand, or the offhand when only
it holds something) and an empty slot passes. The trade (swapItem): a slot locked against taking
(``DisabledSlots`` bit slot + 8) or placing (bit + 16) refuses; a creative player with an empty
slot puts a copy of one item; a hand of one item or none trades whole; more than one item goes
into an empty slot one at a time, and not at all into a full one.

PackTest's ``use entity`` passes the entity's own position as the click (DummyCommand.useEntity:
``entity.position()``, a world position where the game passes one relative to the entity), so
with an empty hand the slot follows the stand's height in the world, as it does in the game.

Items worn by an ``equippable`` component (1.21.2+) other than the game's armour are not read:
such an item goes by its id, as listed above (a pack's equippable component raises Unmodelled).

Sources (decompiled 1.21): world/entity/decoration/ArmorStand.java (interactAt, getClickedSlot,
isDisabled, swapItem, isBaby/getAgeScale), world/entity/LivingEntity.java (getEquipmentSlotForItem),
world/item/Equipable.java, ArmorItem, ElytraItem, ShieldItem, AbstractSkullBlock, CarvedPumpkinBlock.
"""
from __future__ import annotations

import numpy as np

from emulator.world import inventories, living
from emulator.world.errors import Unmodelled
from emulator.world.player_actions import hand_slot

F32 = np.float32
MAINHAND, OFFHAND = inventories.MAINHAND, inventories.OFFHAND
FEET, LEGS, CHEST, HEAD = (inventories.ARMOR_SLOTS[n] for n in ("feet", "legs", "chest", "head"))
# EquipmentSlot.getFilterFlag: the bit of each slot in DisabledSlots
FILTER_FLAG = {MAINHAND: 0, FEET: 1, LEGS: 2, CHEST: 3, HEAD: 4, OFFHAND: 5}
_WORN = {"_helmet": HEAD, "_chestplate": CHEST, "_leggings": LEGS, "_boots": FEET}
_HEADS = ("_head", "_skull")


def equipment_slot_for(stack) -> int:
    """LivingEntity.getEquipmentSlotForItem for an armor stand: the item's Equipable slot (an
    armor stand wears no body armour: ArmorStand.canUseSlot), else the main hand."""
    if stack.component("minecraft:equippable") is not None:
        raise Unmodelled(f"the equippable component of {stack.id} (the slot it is worn in)")
    name = stack.id.removeprefix("minecraft:")
    if name == "turtle_helmet" or name == "carved_pumpkin" or (name.endswith(_HEADS) and name != "piston_head"):
        return HEAD
    if name == "elytra":
        return CHEST
    if name == "shield":
        return OFFHAND
    for suffix, slot in _WORN.items():
        if name.endswith(suffix):
            return slot
    return MAINHAND


def interact_at(state, player, hand: str, stand, at) -> str:
    """ArmorStand.interactAt on the server with the stack in ``hand``, clicked at ``at``."""
    version = state.version
    held_access = inventories.entity_slot(player, hand_slot(hand), version)
    held = held_access.get()
    if stand.data.get("Marker") or held.id == "minecraft:name_tag":
        return "pass"
    if player.gamemode == "spectator":
        return "consume"
    worn = equipment_slot_for(held)
    if held.is_empty:
        clicked = _clicked_slot(state, stand, at)
        slot = worn if _disabled(stand, clicked) else clicked
        if _has(state, stand, slot) and _swap(state, player, held_access, stand, slot):
            return "consume"
        return "pass"
    if _disabled(stand, worn):
        return "fail"
    return "consume" if _swap(state, player, held_access, stand, worn) else "pass"


def _disabled_slots(stand) -> int:
    return int(stand.data.get("DisabledSlots", 0))


def _disabled(stand, slot: int) -> bool:
    """ArmorStand.isDisabled: its DisabledSlots bit, or a hand slot on a stand without arms."""
    hand = slot in (MAINHAND, OFFHAND)
    return bool(_disabled_slots(stand) & 1 << FILTER_FLAG[slot]) or (hand and not stand.data.get("ShowArms"))


def _has(state, stand, slot: int) -> bool:
    return not inventories.entity_slot(stand, slot, state.version).get().is_empty


def _clicked_slot(state, stand, at) -> int:
    """ArmorStand.getClickedSlot: the click's height over the stand's scale picks the slot."""
    small = living.is_baby(stand)
    scale = living.attribute_value(stand, "scale") * (0.5 if small else 1.0)  # getScale() * getAgeScale()
    y = at[1] / float(F32(scale))
    if 0.1 <= y < 0.1 + (0.8 if small else 0.45) and _has(state, stand, FEET):
        return FEET
    if 0.9 + (0.3 if small else 0.0) <= y < 0.9 + (1.0 if small else 0.7) and _has(state, stand, CHEST):
        return CHEST
    if 0.4 <= y < 0.4 + (1.0 if small else 0.8) and _has(state, stand, LEGS):
        return LEGS
    if y >= 1.6 and _has(state, stand, HEAD):
        return HEAD
    if not _has(state, stand, MAINHAND) and _has(state, stand, OFFHAND):
        return OFFHAND
    return MAINHAND


def _swap(state, player, held_access, stand, slot: int) -> bool:
    """ArmorStand.swapItem: the stand's slot and the player's hand trade (see the module's doc)."""
    stand_access = inventories.entity_slot(stand, slot, state.version)
    there, held = stand_access.get(), held_access.get()
    flag = FILTER_FLAG[slot]
    if not there.is_empty and _disabled_slots(stand) & 1 << (flag + 8):
        return False
    if there.is_empty and _disabled_slots(stand) & 1 << (flag + 16):
        return False
    if player.gamemode == "creative" and there.is_empty and not held.is_empty:
        one = held.copy()
        one.count = 1
        stand_access.set(one)
        return True
    if held.is_empty or held.count <= 1:
        stand_access.set(held)
        held_access.set(there)
        return True
    if not there.is_empty:
        return False
    one = held.copy()
    one.count = 1
    held.count -= 1
    stand_access.set(one)
    held_access.set(held)
    return True
