"""Inventories: the slots of entities and container blocks, kept in the NBT the game saves.

The items live where the game saves them, so ``data get``, ``nbt=`` and ``data modify`` (on
blocks, and on non-player entities) see and change the same items the item commands do:
- players: ``Inventory`` (``Slot`` 0-35; before 1.21.5 also 100-103 armor and -106 offhand),
  ``EnderItems``, and from 1.21.5 ``equipment`` {head, chest, legs, feet, offhand, body}; the
  held item is the ``Inventory`` entry of ``SelectedItemSlot``, shown as ``SelectedItem``
  (:func:`selected_item`); the cursor and the 2x2 crafting grid are not saved (kept here);
- other living entities (mobs, armor stands): ``equipment`` {mainhand, offhand, head, chest,
  legs, feet, body} from 1.21.5, ``HandItems`` [main, off], ``ArmorItems`` [feet, legs, chest,
  head] and ``body_armor_item`` before;
- item entities and item frames: ``Item``; item displays: ``item``; container minecarts and
  chest boats: ``Items``;
- container block entities (:data:`CONTAINER_SIZES`): ``Items`` entries with ``Slot``; the
  decorated pot's ``item`` and the jukebox's ``RecordItem`` (:data:`SINGLE_ITEM_BLOCKS`).

A player's hands and armor are reached as slots of the player: ``entity_slot(player, MAINHAND,
state.version)`` is the held stack (what ``dummy use item`` or ``drop`` act on).

API (slot ids are SlotRanges': 0-35 inventory/container, 98/99 hands, 100-103 armor feet..head,
105 body, 200-226 ender chest, 499 cursor, 500-503 crafting)
- ``entity_slot(entity, slot, version)``: a :class:`SlotAccess` (``get()`` an
  :class:`~emulator.world.items.ItemStack`, ``set(stack)`` True when accepted) or None when the
  entity has no such slot (Entity.getSlot returning SlotAccess.NULL).
- ``container(blocks, pos, version)``: the block's :class:`Container` (``size``, ``slot(i)``) or
  None when the block is no container.
- ``player_inventory(player, version)``: :class:`PlayerInventory`: ``add(stack)`` (Inventory.add:
  fills matching stacks, the selected slot and offhand first, then free slots; ``stack`` keeps
  what did not fit; the game's boolean), ``clear_or_count(test, max_count)``
  (ClearInventoryCommands), ``selected`` (the held slot).
- ``MAINHAND``, ``OFFHAND``, ``BODY``, ``CURSOR``, ``ARMOR_SLOTS``: slot ids by name.
- ``selected_item(data)``: the held stack's NBT for ``SelectedItem`` (None when empty).
- ``equipment_defaults(version)``: the empty ``HandItems``/``ArmorItems`` a new mob saves before 1.21.5.
- ``default_block_entity(block_id)``: the block entity a container gets when placed (``Items: []``).
- ``normalise_items(data)``: the item stacks of an entity's or block entity's NBT, as the game
  reads them when it loads that NBT (summon, setblock, ``data``): each one's components patched
  over the item's defaults (a component equal to a default, or a removal of one the item lacks,
  leaves the patch: :func:`emulator.world.items.from_nbt`).
- ``drop_item(store, pos, stack, version, rng, extra)``: an item entity (what ``give`` drops, ``loot
  spawn`` makes, a player would drop); ``throw_from(store, player, stack, version, rng, extra)``:
  one a player throws (Player.createItemStackToDrop: from the eyes, along the look).

Sources (decompiled 1.21): world/entity/player/Player.java and Inventory.java (getSlot, add,
getSlotWithRemainingSpace, save), world/entity/LivingEntity.java (getSlot), world/entity/Mob.java
(HandItems/ArmorItems), world/ContainerHelper.java, world/entity/SlotAccess.java,
advancements/critereon/NbtPredicate.java (SelectedItem); 1.21.5 equipment from the minecraft.wiki
"Entity format" page.
"""
from __future__ import annotations

import math
import weakref
from collections.abc import Callable

import numpy as np

from mcfunction_parser.nbt import Byte, Compound, Double, Int, IntArray, List, Short
from emulator.world import mth
from emulator.world.id_families import COLOURS
from emulator.world.errors import CommandFailure
from emulator.world.items import EMPTY, ItemStack, from_nbt, to_nbt
from emulator.world.living import NOT_LIVING
from emulator.world.nbt_ops import copy_tag, is_numeric, narrow

F32 = np.float32
THROWN_PICKUP_DELAY = 40  # Player.createItemStackToDrop: setPickUpDelay(40)
EQUIPMENT_VERSION = (1, 21, 5)  # 25w02a-25w04a: equipment compound, player armor leaves Inventory
MAINHAND, OFFHAND, BODY, CURSOR = 98, 99, 105, 499
ARMOR_SLOTS = {"feet": 100, "legs": 101, "chest": 102, "head": 103}
ARMOR = {100: "feet", 101: "legs", 102: "chest", 103: "head"}
PLAYER_INVENTORY_SIZE, ENDER_SIZE = 36, 27
_OLD_PLAYER_SLOTS = {OFFHAND: -106, 100: 100, 101: 101, 102: 102, 103: 103}
_SINGLE_ITEM = {"minecraft:item": "Item", "minecraft:item_frame": "Item", "minecraft:glow_item_frame": "Item",
                "minecraft:item_display": "item"}
ENTITY_CONTAINERS = {"minecraft:chest_minecart": 27, "minecraft:hopper_minecart": 5, "minecraft:chest_boat": 27,
                      **{f"minecraft:{w}_chest_boat": 27 for w in "oak spruce birch jungle acacia dark_oak mangrove "
                         "cherry pale_oak".split()}, "minecraft:bamboo_chest_raft": 27}
# slots of entities whose own inventories are not modelled (said so when used): villagers' 300-307,
# horses' saddle 400, chest 499 and 500-514
_UNMODELLED = {**{f"minecraft:{n}": range(300, 308) for n in ("villager", "wandering_trader")},
               **{f"minecraft:{n}": range(400, 515) for n in (
                   "horse donkey mule llama trader_llama camel skeleton_horse zombie_horse").split()}}

CRAFTER = "minecraft:crafter"
# campfires keep four items in ``Items`` but are no Container (Clearable): item commands refuse them
CAMPFIRES = frozenset({"minecraft:campfire", "minecraft:soul_campfire"})
SHULKER_BOXES = frozenset({"minecraft:shulker_box"} | {f"minecraft:{c}_shulker_box" for c in COLOURS})
CONTAINER_SIZES = {
    **{f"minecraft:{n}": 27 for n in ("chest", "trapped_chest", "barrel")}, **{box: 27 for box in SHULKER_BOXES},
    "minecraft:hopper": 5, "minecraft:dispenser": 9, "minecraft:dropper": 9, "minecraft:crafter": 9,
    "minecraft:furnace": 3, "minecraft:smoker": 3, "minecraft:blast_furnace": 3, "minecraft:brewing_stand": 5,
    "minecraft:chiseled_bookshelf": 6,
}
# the RandomizableContainer block entities: those that roll a LootTable when first opened
RANDOMIZABLE_CONTAINERS = frozenset({"minecraft:chest", "minecraft:trapped_chest", "minecraft:barrel", "minecraft:hopper",
                                     "minecraft:dispenser", "minecraft:dropper", CRAFTER, "minecraft:decorated_pot"}
                                    | SHULKER_BOXES)
# ContainerSingleItem block entities: one slot, saved under a key of its own
SINGLE_ITEM_BLOCKS = {"minecraft:decorated_pot": "item", "minecraft:jukebox": "RecordItem"}
# the keys under which entities and block entities save item stacks (a stack, a list of stacks, or
# ``equipment``'s compound of them)
ITEM_KEYS = ("Item", "item", "Items", "HandItems", "ArmorItems", "body_armor_item", "equipment", "Inventory",
             "EnderItems", "RecordItem")


def _new_layout(version) -> bool:
    return tuple(version) >= EQUIPMENT_VERSION


class SlotAccess:
    """One slot: ``get()`` the stack (a copy), ``set(stack)`` True when the slot took it."""

    def __init__(self, get: Callable[[], ItemStack], put: Callable[[ItemStack], None]) -> None:
        self._get, self._put = get, put

    def get(self) -> ItemStack:
        return self._get()

    def set(self, stack: ItemStack) -> bool:
        self._put(stack)
        return True


def _slot_byte(entry) -> int | None:
    slot = entry.get("Slot") if isinstance(entry, Compound) else None
    return int(slot) if isinstance(slot, int) else None


def _list_slot(holder: Compound, key: str, slot: int, version) -> SlotAccess:
    """An entry with ``Slot`` ``slot`` of the list ``holder[key]`` (ContainerHelper's save form)."""

    def get() -> ItemStack:
        entries = holder.get(key)
        for entry in entries if isinstance(entries, List) else ():
            if _slot_byte(entry) == slot:
                return from_nbt(entry)
        return EMPTY.copy()

    def put(stack: ItemStack) -> None:
        entries = holder.get(key)
        kept = [e for e in entries if _slot_byte(e) != slot] if isinstance(entries, List) else []
        if not stack.is_empty:
            entry = Compound(Slot=Byte(slot))
            entry.update(to_nbt(stack, version))
            kept.append(entry)
        kept.sort(key=lambda e: (_slot_byte(e) or 0) & 0xFF)  # saved in slot order (offhand -106 last)
        holder[key] = List(kept)

    return SlotAccess(get, put)


def _key_slot(holder_of: Callable[[bool], Compound | None], key: str, version) -> SlotAccess:
    """A single item under ``key`` of a compound (``Item``, ``equipment.head`` ...); empty removes it."""

    def get() -> ItemStack:
        holder = holder_of(False)
        return from_nbt(holder.get(key)) if holder is not None else EMPTY.copy()

    def put(stack: ItemStack) -> None:
        holder = holder_of(True)
        if stack.is_empty:
            holder.pop(key, None)
        else:
            holder[key] = to_nbt(stack, version)

    return SlotAccess(get, put)


def _index_slot(data: Compound, key: str, index: int, size: int, version) -> SlotAccess:
    """Element ``index`` of a fixed-size list (``HandItems``, ``ArmorItems``; ``{}`` when empty)."""

    def get() -> ItemStack:
        entries = data.get(key)
        return from_nbt(entries[index]) if isinstance(entries, List) and index < len(entries) else EMPTY.copy()

    def put(stack: ItemStack) -> None:
        entries = data.get(key)
        entries = List(entries) if isinstance(entries, List) and len(entries) == size else List(Compound() for _ in range(size))
        entries[index] = Compound() if stack.is_empty else to_nbt(stack, version)
        data[key] = entries

    return SlotAccess(get, put)


def _sub_compound(data: Compound, key: str) -> Callable[[bool], Compound | None]:
    def holder(create: bool) -> Compound | None:
        found = data.get(key)
        if isinstance(found, Compound):
            return found
        if create:
            data[key] = Compound()
            return data[key]
        return None
    return holder


# the cursor and crafting grid of each player (not saved in its NBT)
_UNSAVED: "weakref.WeakKeyDictionary[object, dict[int, ItemStack]]" = weakref.WeakKeyDictionary()


def _unsaved_slot(entity, slot: int) -> SlotAccess:
    slots = _UNSAVED.setdefault(entity, {})
    return SlotAccess(lambda: slots.get(slot, EMPTY).copy(), lambda stack: slots.__setitem__(slot, stack.copy()))


def equipment_defaults(version) -> Compound:
    """What a new mob or armor stand saves of its equipment before 1.21.5 (Mob and
    ArmorStand.addAdditionalSaveData: ``HandItems`` and ``ArmorItems`` always, ``{}`` for an empty
    slot; a pack sets ``HandItems[0]`` in place); from 1.21.5 ``equipment`` only when it holds one."""
    if _new_layout(version):
        return Compound()
    return Compound(HandItems=List(Compound() for _ in range(2)), ArmorItems=List(Compound() for _ in range(4)))


def player_defaults() -> Compound:
    """What a new player saves of its inventories (Player.addAdditionalSaveData): empty lists."""
    return Compound(Inventory=List(), EnderItems=List(), SelectedItemSlot=Int(0))


def selected_slot(data: Compound) -> int:
    selected = data.get("SelectedItemSlot")
    return int(selected) if isinstance(selected, int) and 0 <= int(selected) < 9 else 0


def selected_item(data: Compound) -> Compound | None:
    """NbtPredicate.getEntityTagForPredicate: the held stack as ``SelectedItem`` (None when empty)."""
    stack = _list_slot(data, "Inventory", selected_slot(data), (1, 21, 0)).get()
    if stack.is_empty:
        return None
    entries = data.get("Inventory")
    entry = next(e for e in entries if _slot_byte(e) == selected_slot(data))
    return Compound((k, copy_tag(v)) for k, v in entry.items() if k != "Slot")


# every key of an entity's NBT an equipment slot is read from (either layout, players and mobs)
EQUIPMENT_KEYS = ("equipment", "Inventory", "SelectedItemSlot", "HandItems", "ArmorItems", "body_armor_item")


def equipment_nbt(entity) -> Compound:
    """The part of the entity's NBT its equipment slots are read from (the tags themselves, not copies)."""
    data = entity.data
    return Compound((key, data[key]) for key in EQUIPMENT_KEYS if key in data)


def _equipment_slot(data: Compound, slot: int, version, player: bool) -> SlotAccess | None:
    names = {MAINHAND: "mainhand", OFFHAND: "offhand", BODY: "body", **ARMOR}
    if slot not in names:
        return None
    if _new_layout(version):
        return _key_slot(_sub_compound(data, "equipment"), names[slot], version)
    if player:  # Player.setItemSlot ignores the body slot before 1.21.5, and the set still succeeds
        if slot == BODY:
            return SlotAccess(EMPTY.copy, lambda stack: None)
        return _list_slot(data, "Inventory", _OLD_PLAYER_SLOTS[slot], version)
    if slot in (MAINHAND, OFFHAND):
        return _index_slot(data, "HandItems", slot - MAINHAND, 2, version)
    if slot == BODY:
        return _key_slot(lambda create: data, "body_armor_item", version)
    return _index_slot(data, "ArmorItems", slot - 100, 4, version)


def entity_slot(entity, slot: int, version) -> SlotAccess | None:
    """Entity.getSlot: the slot's access, or None (SlotAccess.NULL) when the entity has none."""
    data = entity.data
    if entity.is_player:
        if 0 <= slot < PLAYER_INVENTORY_SIZE:
            return _list_slot(data, "Inventory", slot, version)
        if 200 <= slot < 200 + ENDER_SIZE:
            return _list_slot(data, "EnderItems", slot - 200, version)
        if slot == MAINHAND:
            return _list_slot(data, "Inventory", selected_slot(data), version)
        if slot == CURSOR or 500 <= slot < 504:
            return _unsaved_slot(entity, slot)
        return _equipment_slot(data, slot, version, player=True)
    if entity.type in _SINGLE_ITEM:
        return _key_slot(lambda create: data, _SINGLE_ITEM[entity.type], version) if slot == 0 else None
    if entity.type in ENTITY_CONTAINERS:
        return _list_slot(data, "Items", slot, version) if 0 <= slot < ENTITY_CONTAINERS[entity.type] else None
    if entity.type in NOT_LIVING:
        return None
    if slot in _UNMODELLED.get(entity.type, ()):
        raise CommandFailure("dpemu.unsupported", f"slot {slot} of {entity.type}", report=True)
    return _equipment_slot(data, slot, version, player=False)


# ---------------------------------------------------------------------- containers
class Container:
    """A container block entity's slots: ``Items`` with ``Slot`` (``size`` slots), or for a
    single-item container (``key``: the decorated pot's ``item``, the jukebox's ``RecordItem``) one.
    A block entity whose setItem does more than store the stack overrides :meth:`_put`."""

    def __init__(self, nbt: Compound, size: int, version, key: str | None = None) -> None:
        self.nbt, self.size, self.version, self.key = nbt, size, version, key

    def slot(self, index: int) -> SlotAccess | None:
        if not 0 <= index < self.size:
            return None
        if self.key is not None:
            access = _key_slot(lambda create: self.nbt, self.key, self.version)
        else:
            access = _list_slot(self.nbt, "Items", index, self.version)
        if type(self)._put is Container._put:
            return access
        return SlotAccess(access.get, lambda stack: self._put(access, index, stack))

    def _put(self, access: SlotAccess, index: int, stack: ItemStack) -> None:
        access.set(stack)


class ShulkerBoxContainer(Container):
    """A shulker box's 27 slots: ShulkerBoxBlockEntity saves ``Items`` only when one holds an item
    (ContainerHelper.saveAllItems with alwaysPutTag false)."""

    def _put(self, access: SlotAccess, index: int, stack: ItemStack) -> None:
        access.set(stack)
        if not self.nbt.get("Items"):
            self.nbt.pop("Items", None)


class CrafterContainer(Container):
    """A crafter's nine slots: CrafterBlockEntity.setItem enables a disabled slot it fills."""

    def _put(self, access: SlotAccess, index: int, stack: ItemStack) -> None:
        disabled = self.nbt.get("disabled_slots")
        if isinstance(disabled, IntArray) and index in [int(v) for v in disabled]:
            self.nbt["disabled_slots"] = IntArray(Int(v) for v in disabled if int(v) != index)
        access.set(stack)


class FurnaceContainer(Container):
    """A furnace's, smoker's or blast furnace's three slots: setting the input to another item
    restarts its cooking (AbstractFurnaceBlockEntity.setItem: :func:`emulator.world.furnaces.input_set`,
    which the world hands its blocks as ``furnace_input_set``)."""

    def __init__(self, nbt: Compound, version, block_id: str, input_set) -> None:
        super().__init__(nbt, 3, version)
        self.block_id, self.input_set = block_id, input_set

    def _put(self, access: SlotAccess, index: int, stack: ItemStack) -> None:
        if index != 0 or self.input_set is None:
            access.set(stack)
            return
        before = access.get()
        access.set(stack)
        self.input_set(self.block_id, self.nbt, before, stack, self.version)


class JukeboxContainer(Container):
    """A jukebox's record: setting it starts or stops its song (JukeboxBlockEntity.setTheItem:
    :func:`emulator.world.jukeboxes.item_set`)."""

    def _put(self, access: SlotAccess, index: int, stack: ItemStack) -> None:
        from emulator.world import jukeboxes  # jukeboxes reads items, as this module does
        access.set(stack)
        jukeboxes.item_set(self.nbt, stack, self.version)


FURNACES = frozenset({"minecraft:furnace", "minecraft:smoker", "minecraft:blast_furnace"})


def container(blocks, pos, version) -> Container | None:
    """The container at ``pos`` (ItemCommands.getContainer), None when the block is none."""
    block_id = blocks.get(pos).id
    nbt = blocks.entity(pos)
    if nbt is None:
        return None
    if block_id == "minecraft:jukebox":
        return JukeboxContainer(nbt, 1, version, SINGLE_ITEM_BLOCKS[block_id])
    if block_id in SINGLE_ITEM_BLOCKS:
        return Container(nbt, 1, version, SINGLE_ITEM_BLOCKS[block_id])
    if block_id == CRAFTER:
        return CrafterContainer(nbt, 9, version)
    if block_id in SHULKER_BOXES:
        return ShulkerBoxContainer(nbt, 27, version)
    if block_id in FURNACES:
        return FurnaceContainer(nbt, version, block_id, blocks.furnace_input_set)
    size = CONTAINER_SIZES.get(block_id)
    return None if size is None else Container(nbt, size, version)


def try_clear(blocks, pos, version) -> None:
    """Clearable.tryClear, which setblock and fill run on the block they are about to replace: a
    Container's items go (Container.clearContent), a campfire's too, a lectern's book
    (LecternBlockEntity.setBook(EMPTY): Book and Page are no longer saved) and a jukebox's record
    (JukeboxBlockEntity.setTheItem(EMPTY) turns its has_record state false)."""
    nbt = blocks.entity(pos)
    if nbt is None:
        return
    block = blocks.get(pos)
    if block.id in CAMPFIRES:
        nbt["Items"] = List()
        return
    if block.id == "minecraft:lectern":
        nbt.pop("Book", None)
        nbt.pop("Page", None)
        return
    held = container(blocks, pos, version)
    for index in range(held.size if held is not None else 0):
        if not held.slot(index).get().is_empty:
            held.slot(index).set(EMPTY.copy())
    if block.id == "minecraft:jukebox" and ("has_record", "true") in block.properties:
        blocks.set_state(pos, type(block)(block.id, tuple((k, "false" if k == "has_record" else v)
                                                          for k, v in block.properties)))


def crafter_loaded(nbt: Compound) -> None:
    """CrafterBlockEntity.loadAdditional then saveAdditional: ``crafting_ticks_remaining`` and
    ``triggered`` read as ints (getInt: 0 when missing or not a number), ``disabled_slots`` the
    listed slots 0 - 8 that hold no item (slotCanBeDisabled), saved in slot order."""
    for key in ("crafting_ticks_remaining", "triggered"):
        value = nbt.get(key)
        nbt[key] = Int(narrow(value, Int) if is_numeric(value) else 0)
    wanted = nbt.get("disabled_slots")
    wanted = {int(v) for v in wanted} if isinstance(wanted, IntArray) else set()
    slots = Container(nbt, 9, None)
    nbt["disabled_slots"] = IntArray(Int(i) for i in range(9) if i in wanted and slots.slot(i).get().is_empty)


def normalise_items(data: Compound) -> None:
    """Each stack under :data:`ITEM_KEYS` with its components read as the game's codec builds the
    stack (PatchedDataComponentMap.fromPatch: applyPatch); other fields stay as given."""
    for key in ITEM_KEYS:
        value = data.get(key)
        if isinstance(value, List):
            stacks = list(value)
        elif isinstance(value, Compound):
            stacks = list(value.values()) if key == "equipment" else [value]
        else:
            continue
        for tag in stacks:
            if isinstance(tag, Compound) and isinstance(tag.get("components"), Compound):
                patch = from_nbt(tag).patch
                if patch:
                    tag["components"] = patch
                else:
                    del tag["components"]


def default_block_entity(block_id: str, triggered: bool = False) -> Compound | None:
    """What a container saves when placed empty (ContainerHelper.saveAllItems always writes Items;
    a single-item container writes its item only when it has one; a crafter its crafting ticks
    left and whether it is triggered too)."""
    if block_id in SINGLE_ITEM_BLOCKS:
        return Compound()
    if block_id in CAMPFIRES:  # CampfireBlockEntity.saveAdditional: its four items and cooking times
        return Compound(Items=List(), CookingTimes=IntArray([Int(0)] * 4), CookingTotalTimes=IntArray([Int(0)] * 4))
    if block_id == CRAFTER:  # CrafterBlockEntity.saveAdditional; newBlockEntity: triggered as the state
        return Compound(crafting_ticks_remaining=Int(0), Items=List(), triggered=Int(int(triggered)),
                        disabled_slots=IntArray())
    return Compound(Items=List()) if block_id in CONTAINER_SIZES else None


# ---------------------------------------------------------------------- the player's inventory
class PlayerInventory:
    """Inventory's indices: 0-35 items, 36-39 armor (feet..head), 40 offhand."""

    def __init__(self, player, version) -> None:
        self.player, self.version = player, version

    def _access(self, index: int) -> SlotAccess:
        if index < PLAYER_INVENTORY_SIZE:
            return entity_slot(self.player, index, self.version)
        slot = OFFHAND if index == 40 else 100 + index - 36
        return entity_slot(self.player, slot, self.version)

    @property
    def selected(self) -> int:
        return selected_slot(self.player.data)

    def _has_room(self, index: int, stack: ItemStack) -> bool:
        there = self._access(index).get()
        return (not there.is_empty and there.same_item_same_components(stack) and there.max_stack_size > 1
                and there.count < there.max_stack_size)

    def _slot_with_room(self, stack: ItemStack) -> int:
        for index in (self.selected, 40, *range(PLAYER_INVENTORY_SIZE)):
            if self._has_room(index, stack):
                return index
        return -1

    def _free_slot(self) -> int:
        return next((i for i in range(PLAYER_INVENTORY_SIZE) if self._access(i).get().is_empty), -1)

    def add(self, stack: ItemStack) -> bool:
        """Inventory.add: moves what fits out of ``stack`` (its count drops to what is left). True
        as the game answers: when the last pass moved something (or the player has infinite
        materials, whose inventory takes everything); a damaged item only into a free slot."""
        if stack.is_empty:
            return False
        creative = self.player.gamemode == "creative"
        if stack.is_damaged():
            free = self._free_slot()
            if free >= 0:
                self._access(free).set(stack.copy())
            elif not creative:
                return False
            stack.count = 0
            return True
        while True:
            before = stack.count
            self._add_resource(stack)
            if stack.is_empty or stack.count >= before:
                break
        if stack.count == before and creative:
            stack.count = 0
            return True
        return stack.count < before

    def _add_resource(self, stack: ItemStack) -> None:
        """Inventory.addResource: onto the first stack with room, else into the first free slot."""
        index = self._slot_with_room(stack)
        if index < 0:
            index = self._free_slot()
        if index < 0:
            return
        access = self._access(index)
        there = access.get()
        if there.is_empty:
            there = ItemStack(stack.id, 0, copy_tag(stack.patch), copy_tag(stack.tag))
        moved = max(0, min(stack.count, stack.max_stack_size - there.count))
        there.count += moved
        stack.count -= moved
        access.set(there)

    def clear_or_count(self, test: Callable[[ItemStack], bool], max_count: int) -> int:
        """Inventory.clearOrCountMatchingItems then the crafting grid and the cursor: with
        ``max_count`` 0 only counts; -1 removes every match; returns the count."""
        total = 0
        accesses = [self._access(i) for i in range(41)]
        accesses += [entity_slot(self.player, s, self.version) for s in (500, 501, 502, 503, CURSOR)]
        for access in accesses:
            stack = access.get()
            if stack.is_empty or not test(stack):
                continue
            if max_count == 0:
                total += stack.count
                continue
            take = stack.count if max_count < 0 else min(max_count - total, stack.count)
            total += take
            stack.count -= take
            access.set(stack)
            if max_count > 0 and total >= max_count:
                break
        return total


def player_inventory(player, version) -> PlayerInventory:
    return PlayerInventory(player, version)


def throw_from(store, player, stack: ItemStack, version, rng, extra: Compound | None = None):
    """Player.createItemStackToDrop (not thrown around): an item entity at the eyes minus 0.3, in
    the player's level, with a pickup delay of 40, thrown 0.3 along the look with a little random
    spread (drawn from the emulator's random, not the player's own: the game's values differ);
    ``extra`` NBT overrides."""
    pitch, yaw = F32(player.pitch) * F32(math.pi / 180), F32(player.yaw) * F32(math.pi / 180)
    sin_p, cos_p, sin_y, cos_y = mth.sin(pitch), mth.cos(pitch), mth.sin(yaw), mth.cos(yaw)
    angle, spread = F32(rng.random()) * F32(math.pi * 2), F32(0.02) * F32(rng.random())
    motion = List([Double(float(-sin_y * cos_p * F32(0.3)) + math.cos(angle) * float(spread)),
                   Double(float(-sin_p * F32(0.3) + F32(0.1) + (F32(rng.random()) - F32(rng.random())) * F32(0.1))),
                   Double(float(cos_y * cos_p * F32(0.3)) + math.sin(angle) * float(spread))])
    x, y, z = player.pos
    data = Compound(PickupDelay=Short(THROWN_PICKUP_DELAY), Motion=motion)
    data.update(extra or {})
    return drop_item(store, (x, y + float(player.eye_height) - float(F32(0.3)), z), stack, version, rng, data,
                     player.dimension)


def drop_item(store, pos, stack: ItemStack, version, rng, extra: Compound | None = None,
              dimension: str = "minecraft:overworld"):
    """An item entity holding ``stack`` at ``pos`` in ``dimension`` (ItemEntity's constructor: a
    pickup delay of 10, random motion drawn from ``rng``); ``extra`` NBT overrides (``PickupDelay``,
    ``Owner`` ...)."""
    data = Compound(Item=to_nbt(stack, version), PickupDelay=Short(10), Age=Short(0), Health=Short(5))
    data["Motion"] = List([Double(rng.random() * 0.2 - 0.1), Double(0.2), Double(rng.random() * 0.2 - 0.1)])
    data.update(extra or {})
    return store.summon("minecraft:item", pos, data, dimension=dimension)
