"""What an entity's equipment does to its attributes (1.21+): each equipped item's attribute
modifiers, held while the item stays in its slot.

- ``item_modifiers(stack, version) -> list[Modifier]``: the stack's ``attribute_modifiers``
  component as a pack patched it, else the vanilla item's default (Item.Properties.attributes:
  swords, axes, pickaxes, shovels and hoes from SwordItem/DiggerItem.createAttributes with the
  tier's damage bonus, Tiers.getAttackDamageBonus; the trident and the mace from
  TridentItem/MaceItem.createAttributes).
- ``collect_changes(state, entity, last)``: LivingEntity.collectEquipmentChanges, once per entity
  tick (``tick(state)``, with ``tick_is_idle(state)`` for a batch of ticks):
  for each slot whose stack changed (ItemStack.matches) the old stack's modifiers for that slot are
  removed, then the new stack's are added as transient modifiers (AttributeInstance.
  addTransientModifier): ``attribute … get`` and ``attribute … modifier value get`` see them and so
  does the damage a swing deals, but the entity's ``attributes`` NBT does not (AttributeInstance.
  save keeps only permanent modifiers). An item put in a slot counts from the entity's next tick,
  as in the game (a swing in the same tick as ``item replace`` hits without the weapon's damage).
  A player's tick that finds another item in its main hand (not ItemStack.isSameItem) restarts
  the swing's recharge (Player.tick -> resetAttackStrengthTicker).

The vanilla armour pieces (ArmorItem: ArmorMaterials' defense, toughness and knockback resistance,
named ``armor.<piece>``) count too, so a worn piece reduces damage (CombatRules.getDamageAfterAbsorb).

Not modelled (Unmodelled): body armour (wolf and horse armour), copper tools and armour and spears
(later releases' materials), every equipment modifier below 1.21 (the UUID form), and
enchantments' location-based attribute effects (EnchantmentHelper.runLocationChangedEffects).

Sources (decompiled 1.21): world/entity/LivingEntity.java (detectEquipmentUpdates,
collectEquipmentChanges), world/entity/player/Player.java (tick), world/item/{SwordItem,
DiggerItem,TridentItem,MaceItem,Tiers,Items,ArmorItem,ArmorMaterials}.java,
world/entity/EquipmentSlotGroup.java, world/item/component/ItemAttributeModifiers.java.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from emulator.world import inventories, living
from emulator.world.errors import Unmodelled
from emulator.world.items import EMPTY, ItemStack
from emulator.world.nbt_ops import copy_tag, is_numeric, numeric_value, tags_equal
from mcfunction_parser.nbt import Compound, List

F32 = np.float32
MODIFIERS_VERSION = (1, 21, 0)  # modifiers named by id (1.20.5's by UUID are not modelled)
BASE_ATTACK_DAMAGE = "minecraft:base_attack_damage"  # Item.BASE_ATTACK_DAMAGE_ID
BASE_ATTACK_SPEED = "minecraft:base_attack_speed"
TIER_BONUS = {"wooden": 0.0, "stone": 1.0, "iron": 2.0, "diamond": 3.0, "golden": 0.0, "netherite": 4.0}
# Items: DiggerItem.createAttributes(tier, damage, speed) per tool and material
_MATERIALS = ("wooden", "stone", "golden", "iron", "diamond", "netherite")
DIGGERS = {
    "axe": dict(zip(_MATERIALS, ((6.0, -3.2), (7.0, -3.2), (6.0, -3.0), (6.0, -3.1), (5.0, -3.0), (5.0, -3.0)))),
    "pickaxe": dict.fromkeys(_MATERIALS, (1.0, -2.8)),
    "shovel": dict.fromkeys(_MATERIALS, (1.5, -3.0)),
    "hoe": dict(zip(_MATERIALS, ((0.0, -3.0), (-1.0, -2.0), (0.0, -3.0), (-2.0, -1.0), (-3.0, 0.0), (-4.0, 0.0)))),
}
SLOTS = {inventories.MAINHAND: "mainhand", inventories.OFFHAND: "offhand", inventories.BODY: "body",
         **{slot: name for name, slot in inventories.ARMOR_SLOTS.items()}}
# EquipmentSlotGroup: the slots each group names
GROUPS = {"any": frozenset(SLOTS.values()), "hand": frozenset({"mainhand", "offhand"}),
          "armor": frozenset({"feet", "legs", "chest", "head"}),
          **{name: frozenset({name}) for name in SLOTS.values()}}
# ArmorMaterials: (defense of boots, leggings, chestplate, helmet), toughness, knockback resistance
ARMOUR = {"leather": ((1, 2, 3, 1), 0.0, 0.0), "chainmail": ((1, 4, 5, 2), 0.0, 0.0),
          "iron": ((2, 5, 6, 2), 0.0, 0.0), "golden": ((1, 3, 5, 2), 0.0, 0.0),
          "diamond": ((3, 6, 8, 3), 2.0, 0.0), "turtle": ((2, 5, 6, 2), 0.0, 0.0),
          "netherite": ((3, 6, 8, 3), 3.0, 0.1)}
PIECES = {"boots": "feet", "leggings": "legs", "chestplate": "chest", "helmet": "head"}  # ArmorItem.Type


@dataclass(frozen=True)
class Modifier:
    attribute: str  # the short id (living.attribute_id)
    id: str
    amount: float
    operation: str
    slot: str  # an EquipmentSlotGroup name


def _f(value: float) -> float:
    """A float constant as the double the game stores ((double) of a Java float)."""
    return float(F32(value))


def default_modifiers(item_id: str) -> list[Modifier]:
    """The item's default attribute modifiers (its attribute_modifiers component as the item registers it)."""
    name = item_id.removeprefix("minecraft:")
    material, _, kind = name.rpartition("_")
    if kind == "sword" and material in TIER_BONUS:  # SwordItem.createAttributes(tier, 3, -2.4F)
        damage, speed = _f(3.0 + TIER_BONUS[material]), _f(-2.4)
    elif kind in DIGGERS and material in DIGGERS[kind]:  # DiggerItem.createAttributes
        damage, speed = _f(DIGGERS[kind][material][0] + TIER_BONUS[material]), _f(DIGGERS[kind][material][1])
    elif name == "trident":
        damage, speed = 8.0, _f(-2.9)
    elif name == "mace":
        damage, speed = 5.0, _f(-3.4)
    elif kind in PIECES and material in ARMOUR:
        return _armour(material, kind)
    else:
        if name == "wolf_armor" or name.endswith("_horse_armor"):
            raise Unmodelled(f"the default attribute modifiers of {item_id} (body armour)")
        if name.endswith("_spear") or (material == "copper" and (kind in PIECES or kind in DIGGERS
                                                                 or kind == "sword")):
            raise Unmodelled(f"the default attribute modifiers of {item_id}")
        return []
    return [Modifier("attack_damage", BASE_ATTACK_DAMAGE, damage, "add_value", "mainhand"),
            Modifier("attack_speed", BASE_ATTACK_SPEED, speed, "add_value", "mainhand")]


def _armour(material: str, piece: str) -> list[Modifier]:
    """ArmorItem's default modifiers: armor (the material's defense for the piece) and toughness,
    knockback resistance when above 0, all named ``armor.<piece>`` in the piece's slot."""
    defense, toughness, resistance = ARMOUR[material]
    slot, modifier_id = PIECES[piece], f"minecraft:armor.{piece}"
    found = [Modifier("armor", modifier_id, float(defense[tuple(PIECES).index(piece)]), "add_value", slot),
             Modifier("armor_toughness", modifier_id, toughness, "add_value", slot)]
    if resistance > 0:
        found.append(Modifier("knockback_resistance", modifier_id, _f(resistance), "add_value", slot))
    return found


def _from_component(tag) -> list[Modifier]:
    """ItemAttributeModifiers.CODEC: ``{modifiers: [...]}`` (a bare list from 1.21.5)."""
    entries = tag.get("modifiers", List()) if isinstance(tag, Compound) else tag
    found = []
    for entry in entries or ():
        if not isinstance(entry, Compound):
            continue
        amount = entry.get("amount")
        found.append(Modifier(living.attribute_id(str(entry.get("type", ""))), str(entry.get("id", "")),
                              float(numeric_value(amount)) if is_numeric(amount) else 0.0,
                              str(entry.get("operation", "add_value")), str(entry.get("slot", "any"))))
    return found


def item_modifiers(stack: ItemStack, version) -> list[Modifier]:
    """ItemStack.forEachModifier's item modifiers: the patched component, else the item's default."""
    if stack.is_empty:
        return []
    if tuple(version) < MODIFIERS_VERSION:
        raise Unmodelled(f"the attribute modifiers of {stack.id} before 1.21")
    if "!minecraft:attribute_modifiers" in stack.patch:
        return []
    if "minecraft:attribute_modifiers" in stack.patch:
        return _from_component(stack.patch["minecraft:attribute_modifiers"])
    return default_modifiers(stack.id)


def _for_slot(state, stack: ItemStack, slot_name: str) -> list[Modifier]:
    """The stack's modifiers for the slot; what is not modelled is reported (a warning that makes a
    test inconclusive, once per change of the slot) and counts as none."""
    try:
        return [m for m in item_modifiers(stack, state.version) if slot_name in GROUPS.get(m.slot, ())]
    except Unmodelled as unmodelled:
        state.error(str(unmodelled.reason), severity="warning", unmodelled=True)
        return []


@dataclass
class _Seen:
    """What an entity's last equipment check saw: its slots' stacks and, as a copy, the NBT they were
    read from (while that NBT is the same, Tag.equals, no slot can have changed: the check skips
    reading them, the common tick)."""
    slots: dict = field(default_factory=dict)
    nbt: Compound | None = None
    absent: tuple = ()  # the keys of EQUIPMENT_KEYS not in that NBT

    def saw(self, entity) -> None:
        """Keep a copy of the NBT the entity's slots are read from now."""
        self.nbt = copy_tag(inventories.equipment_nbt(entity))
        self.absent = tuple(key for key in inventories.EQUIPMENT_KEYS if key not in self.nbt)


def _nbt_changed(entity, seen: _Seen) -> bool:
    if seen.nbt is None:
        return True
    data = entity.data
    for key, then in seen.nbt.items():  # the keys there last time (a player's two), then the others
        now = data.get(key)
        if now is None or not tags_equal(now, then):
            return True
    for key in seen.absent:
        if key in data:
            return True
    return False


def _changed_slots(state, entity, last: dict) -> dict:
    """The slots whose stack is no longer the one last seen (LivingEntity.equipmentHasChanged:
    not ItemStack.matches), with their new stacks."""
    changed = {}
    for slot in SLOTS:
        access = inventories.entity_slot(entity, slot, state.version)
        stack = access.get() if access is not None else EMPTY
        old = last.get(slot, EMPTY)
        if not (old.is_empty and stack.is_empty or (old.id == stack.id and old.count == stack.count
                                                     and old.same_item_same_components(stack))):
            changed[slot] = stack
    return changed


def collect_changes(state, entity, last: dict) -> None:
    """LivingEntity.collectEquipmentChanges against ``last`` ({slot: the stack last seen}): the
    changed slots' old modifiers off, then the new ones on."""
    changed = _changed_slots(state, entity, last)
    held = changed.get(inventories.MAINHAND)
    if entity.is_player and held is not None and held.id != last.get(inventories.MAINHAND, EMPTY).id:
        living.reset_attack_strength(state, entity)  # Player.tick: another item in the main hand
    for slot in changed:
        for modifier in _for_slot(state, last.get(slot, EMPTY), SLOTS[slot]):
            living.set_transient(entity, modifier.attribute, modifier.id, None)
    for slot, stack in changed.items():
        last[slot] = stack.copy()
        for modifier in _for_slot(state, stack, SLOTS[slot]):
            if living.has_attribute(entity.type, modifier.attribute):
                living.set_transient(entity, modifier.attribute, modifier.id, (modifier.amount, modifier.operation))


def tick(state) -> None:
    """Each living entity's equipment check (LivingEntity.tick -> detectEquipmentUpdates)."""
    if tuple(state.version) < MODIFIERS_VERSION:
        return
    for entity in state.entities.living_mobs():
        last = entity.equipment_seen
        if last is None:
            last = entity.equipment_seen = _Seen()
        if not _nbt_changed(entity, last):
            continue
        collect_changes(state, entity, last.slots)
        last.saw(entity)


def tick_is_idle(state) -> bool:
    """Whether :func:`tick` would change nothing now."""
    if tuple(state.version) < MODIFIERS_VERSION:
        return True
    for entity in state.entities.living_mobs():
        last = entity.equipment_seen or _Seen()
        if _nbt_changed(entity, last) and _changed_slots(state, entity, last.slots):
            return False
    return True
