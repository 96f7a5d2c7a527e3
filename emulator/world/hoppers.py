"""Hoppers moving items: what a hopper block entity does when its cooldown runs out.

- ``transfer(state, dimension, blocks, pos, nbt, ticked) -> bool``: HopperBlockEntity.tryMoveItems
  for the hopper at ``pos`` whose cooldown is over: unless locked (``enabled=false``), it pushes one
  item into the container it faces (ejectItems), then, unless full, pulls one item from the
  container above or takes in the item entities over it (suckInItems); when it moved anything
  its ``TransferCooldown`` becomes 8. ``ticked`` holds the hoppers that already ticked this game
  tick (the game's ``tickedGameTime``, which is not saved).
- ``still(state, dimension, blocks, pos, nbt) -> bool``: whether a transfer could move nothing
  (cheap: the idle test of a tick).
- ``container_at(state, dimension, blocks, pos, what) -> Target | None`` (getContainerAt) and
  ``add_item(source, target, stack, face, ticked) -> ItemStack`` (addItem: what is left), which a
  crafter uses too.

Containers modelled: chests and trapped chests (a double chest is one 54-slot container, its
``type=right`` half first: ChestBlock.getBlockType, DoubleBlockCombiner), barrels, dispensers,
droppers, hoppers, shulker boxes (which refuse shulker boxes: ShulkerBoxBlockEntity.
canPlaceItemThroughFace) and the furnace family by face (AbstractFurnaceBlockEntity.getSlotsForFace:
from above the input, from the sides the fuel, which takes only fuels and a bucket, from below the
output and an empty or water bucket out of the fuel slot), composters (:mod:`emulator.world.composters`:
from above one compostable at a time below level 7, from below the bone meal of a ready one) and
brewing stands (:mod:`emulator.world.brewing`: from above the ingredient, from a side the bottles
and blaze powder, from below the bottles and a glass bottle left in the ingredient slot). Stacking (tryMoveInItem/canMergeItems):
the same item and components, up to the moving stack's max stack size. An item entity over the
hopper (the box from 11/16 above its floor to the top of the block above) is taken in whole or in
part, unless the block above is a full cube that does not let hoppers through
(``#does_not_block_hoppers``). A hopper that filled an empty hopper which has not ticked yet this
tick gives it a cooldown of 8, one that has ticked 7.

Not modelled, reported when a hopper would use them: crafters, chiseled bookshelves, decorated pots
and jukeboxes as containers, container entities (minecarts, chest boats)
in the block faced or above; hopper minecarts do not pull items. Comparators do not see changes.

Sources (decompiled 1.21): world/level/block/entity/HopperBlockEntity.java (pushItemsTick,
tryMoveItems, inventoryFull, ejectItems, isFullContainer, suckInItems, tryTakeInItemFromSlot,
addItem, tryMoveInItem, canMergeItems, getItemsAtAndAbove, getBlockContainer, getEntityContainer),
Hopper.SUCK_AABB, ChestBlock.getContainer, BrewingStandBlockEntity (getSlotsForFace, canPlaceItem,
canTakeItemThroughFace), AbstractFurnaceBlockEntity (getSlotsForFace, canPlaceItem,
canTakeItemThroughFace), ShulkerBoxBlockEntity, ComposterBlock.getContainer (InputContainer,
OutputContainer, EmptyContainer), world/phys/AABB.intersects (strict).
"""
from __future__ import annotations

import math

from emulator.world import block_shapes, brewing, composters, furnaces, inventories
from emulator.world.errors import Unmodelled
from emulator.world.items import EMPTY, ItemStack
from emulator.world.nbt_ops import int_at
from mcfunction_parser.nbt import Int

COOLDOWN = 8  # HopperBlockEntity.MOVE_ITEM_SPEED
OFFSETS = {"down": (0, -1, 0), "up": (0, 1, 0), "north": (0, 0, -1), "south": (0, 0, 1), "west": (-1, 0, 0),
           "east": (1, 0, 0)}
OPPOSITE = {"down": "up", "up": "down", "north": "south", "south": "north", "west": "east", "east": "west"}
_CLOCKWISE = {"north": "east", "east": "south", "south": "west", "west": "north"}
_COUNTER_CLOCKWISE = {v: k for k, v in _CLOCKWISE.items()}
_CHESTS = frozenset({"minecraft:chest", "minecraft:trapped_chest"})
_PLAIN = frozenset({"minecraft:barrel", "minecraft:dispenser", "minecraft:dropper", "minecraft:hopper"}) | _CHESTS
# Containers whose rules for hoppers are not modelled here
_UNMODELLED = frozenset({"minecraft:crafter", "minecraft:chiseled_bookshelf", "minecraft:decorated_pot",
                         "minecraft:jukebox"})
BREWING_STAND = "minecraft:brewing_stand"
_SUCK_FLOOR = 11 / 16  # Hopper.SUCK_AABB: Block.box(0, 11, 0, 16, 32, 16)


def _properties(block) -> dict:
    return dict(block.properties)


class _Joined:
    """CompoundContainer: two chests' 27 slots each, as one."""

    def __init__(self, first, second) -> None:
        self.first, self.second, self.size = first, second, first.size + second.size

    def slot(self, index: int):
        return self.first.slot(index) if index < self.first.size else self.second.slot(index - self.first.size)


class Target:
    """A container as a hopper sees it: its slots, and which of them each face reaches."""

    def __init__(self, block_id: str, slots, pos, resources=None, version=None) -> None:
        self.block_id, self.slots, self.pos, self.resources, self.version = block_id, slots, pos, resources, version

    @property
    def size(self) -> int:
        return self.slots.size

    def get(self, index: int) -> ItemStack:
        return self.slots.slot(index).get()

    def put(self, index: int, stack: ItemStack) -> None:
        self.slots.slot(index).set(stack)

    def is_empty(self) -> bool:
        return all(self.get(i).is_empty for i in range(self.size))

    def slots_for(self, face: str | None) -> range | tuple[int, ...]:
        """WorldlyContainer.getSlotsForFace (every slot of another container, or with no face)."""
        if face is not None and self.block_id in furnaces.FURNACES:
            return (2, 1) if face == "down" else (0,) if face == "up" else (1,)
        if face is not None and self.block_id == BREWING_STAND:
            return brewing.slots_for(face)
        return range(self.size)

    def can_place(self, index: int, stack: ItemStack, face: str | None) -> bool:
        """canPlaceItem, and canPlaceItemThroughFace when entered through a face."""
        if self.block_id in furnaces.FURNACES:
            if index == 2:
                return False
            if index == 1:
                return (stack.id == "minecraft:bucket" and self.get(1).id != "minecraft:bucket") or \
                    furnaces.is_fuel(stack, self.resources)
            return True
        if self.block_id == BREWING_STAND:
            return brewing.can_place([self.get(i) for i in range(3)], index, stack, self.version)
        if face is not None and self.block_id in inventories.SHULKER_BOXES:
            return stack.id not in inventories.SHULKER_BOXES
        return True

    def can_take(self, index: int, stack: ItemStack, face: str) -> bool:
        """canTakeItemThroughFace."""
        if self.block_id in furnaces.FURNACES and face == "down" and index == 1:
            return stack.id in ("minecraft:water_bucket", "minecraft:bucket")
        if self.block_id == BREWING_STAND:
            return brewing.can_take(index, stack)
        return True


class _Composter(Target):
    """ComposterBlock.getContainer: at level 8 an output of one bone meal, taken from below (which
    empties it: OutputContainer.setChanged); below 7 an input that takes one compostable from above
    into the composter (InputContainer.setChanged: ComposterBlock.addItem); at 7 no slot."""

    def __init__(self, state, dimension, blocks, pos) -> None:
        super().__init__(composters.COMPOSTER, None, pos, state.resources)
        self.state, self.dimension, self.blocks = state, dimension, blocks
        self.level = composters.level(blocks.get(pos))

    @property
    def size(self) -> int:
        return 0 if self.level == composters.FULL else 1

    def get(self, index: int) -> ItemStack:
        return ItemStack("minecraft:bone_meal", 1) if self.level == composters.READY else EMPTY.copy()

    def put(self, index: int, stack: ItemStack) -> None:
        if self.level == composters.READY:
            composters.empty(self.blocks, self.pos)
        elif not stack.is_empty:
            composters.add_item(self.state, self.dimension, self.blocks, self.pos, stack.id)

    def is_empty(self) -> bool:
        return self.level != composters.READY

    def slots_for(self, face: str | None) -> tuple[int, ...]:
        if self.level == composters.READY:
            return (0,) if face == "down" else ()
        return (0,) if face == "up" and self.level < composters.FULL else ()

    def can_place(self, index: int, stack: ItemStack, face: str | None) -> bool:
        return (face == "up" and self.level < composters.FULL
                and composters.chance(stack.id, self.state.version) is not None)

    def can_take(self, index: int, stack: ItemStack, face: str) -> bool:
        return self.level == composters.READY and face == "down" and stack.id == "minecraft:bone_meal"



def _chest_slots(blocks, pos, block, version):
    """ChestBlock.getContainer(ignoring what blocks it): a chest joined with the chest it pairs with."""
    own = inventories.container(blocks, pos, version)
    props = _properties(block)
    kind, facing = props.get("type", "single"), props.get("facing", "north")
    if kind == "single" or facing not in _CLOCKWISE:
        return own
    side = _CLOCKWISE[facing] if kind == "left" else _COUNTER_CLOCKWISE[facing]
    other_pos = tuple(p + d for p, d in zip(pos, OFFSETS[side]))
    other = blocks.get(other_pos)
    other_props = _properties(other)
    if other.id != block.id or other_props.get("type", "single") in ("single", kind) \
            or other_props.get("facing") != facing or blocks.entity(other_pos) is None:
        return own
    other_slots = inventories.container(blocks, other_pos, version)
    return _Joined(own, other_slots) if kind == "right" else _Joined(other_slots, own)


def _box_holds(entity, box) -> bool:
    """AABB.intersects (strict) of the entity's bounding box and ``box``."""
    low = entity.bounding_box
    return all(low[i] < box[i + 3] and low[i + 3] > box[i] for i in range(3))


def _container_entity_in(state, dimension, pos, what: str) -> None:
    """HopperBlockEntity.getEntityContainer: a container entity in the block's cube (not modelled)."""
    box = (*pos, *(p + 1 for p in pos))
    for entity in state.entities.entities:
        if entity.alive and entity.dimension == dimension and entity.type in inventories.ENTITY_CONTAINERS \
                and _box_holds(entity, box):
            raise Unmodelled(f"{what} a {entity.type}")


def container_at(state, dimension, blocks, pos, what: str) -> Target | None:
    """HopperBlockEntity.getContainerAt: the block's container, else a container entity in the
    block (not modelled: ``what`` names who uses it); None when there is neither."""
    block = blocks.get(pos)
    if block.id in _UNMODELLED:
        raise Unmodelled(f"{what} {block.id}")
    if block.id == composters.COMPOSTER:
        return _Composter(state, dimension, blocks, pos)
    slots = None
    if block.id in _CHESTS:
        slots = _chest_slots(blocks, pos, block, state.version)
    elif block.id in _PLAIN or block.id in inventories.SHULKER_BOXES or block.id in furnaces.FURNACES \
            or block.id == BREWING_STAND:
        slots = inventories.container(blocks, pos, state.version)
    if slots is not None:
        return Target(block.id, slots, pos, state.resources, state.version)
    _container_entity_in(state, dimension, pos, what)
    return None


# ---------------------------------------------------------------------- moving one item
def add_item(source: Target | None, target: Target, stack: ItemStack, face: str | None, ticked: set) -> ItemStack:
    """HopperBlockEntity.addItem: into each slot the face reaches, in turn; what is left. ``source``
    is the hopper it comes from (None for anything else), ``ticked`` the hoppers that ticked this tick."""
    for index in target.slots_for(face):
        if stack.is_empty:
            break
        stack = _move_in(source, target, stack, index, face, ticked)
    return stack


def _move_in(source: Target | None, target: Target, stack: ItemStack, index: int, face: str | None,
             ticked: set) -> ItemStack:
    """HopperBlockEntity.tryMoveInItem: into an empty slot whole, onto the same item and components
    up to the moving stack's max stack size. An empty hopper filled by it that is not on a custom
    cooldown (over 8) waits 8 ticks, 7 when the source is a hopper that ticked no later than it."""
    if not target.can_place(index, stack, face):
        return stack
    there = target.get(index)
    was_empty = target.is_empty()
    moved = False
    if there.is_empty:
        target.put(index, stack)
        stack, moved = EMPTY.copy(), True
    elif there.count <= there.max_stack_size and there.same_item_same_components(stack):
        moving = min(stack.count, stack.max_stack_size - there.count)
        if moving > 0:
            there.count += moving
            target.put(index, there)
            stack = stack.copy()
            stack.count -= moving
            moved = True
    if moved and was_empty and target.block_id == "minecraft:hopper":
        nbt = target.slots.nbt
        if int_at(nbt, "TransferCooldown") <= COOLDOWN:
            already = source is not None and source.block_id == "minecraft:hopper" and target.pos in ticked
            nbt["TransferCooldown"] = Int(COOLDOWN - (1 if already else 0))
    return stack


def _one_out(source: Target, index: int, target: Target, face: str | None, ticked: set) -> bool:
    """removeItem(index, 1) added to ``target``: True when it went in; else the slot is as it was."""
    stack = source.get(index)
    one = stack.copy()
    one.count = 1
    if not add_item(source, target, one, face, ticked).is_empty:
        return False
    stack.count -= 1
    source.put(index, stack if stack.count > 0 else EMPTY.copy())
    return True


# ---------------------------------------------------------------------- the hopper's transfer
def _hopper(state, blocks, pos, nbt) -> Target:
    return Target("minecraft:hopper", inventories.Container(nbt, 5, state.version), pos, state.resources, state.version)


def _full(target: Target, face: str) -> bool:
    """HopperBlockEntity.isFullContainer: every slot the face reaches at its max stack size (an
    empty slot counts 0 of 64)."""
    return all(s.count >= s.max_stack_size for s in map(target.get, target.slots_for(face)))


def _inventory_full(hopper: Target) -> bool:
    """HopperBlockEntity.inventoryFull: every slot holds exactly its max stack size."""
    return all(not s.is_empty and s.count == s.max_stack_size for s in map(hopper.get, range(hopper.size)))


def _eject(state, dimension, blocks, pos, hopper: Target, ticked: set) -> bool:
    facing = _properties(blocks.get(pos)).get("facing", "down")
    there = tuple(p + d for p, d in zip(pos, OFFSETS[facing]))
    target = container_at(state, dimension, blocks, there, "a hopper pushing items into")
    if target is None:
        return False
    face = OPPOSITE[facing]
    if _full(target, face):
        return False
    return any(not hopper.get(i).is_empty and _one_out(hopper, i, target, face, ticked) for i in range(hopper.size))


def _blocks_hoppers(state, block) -> bool:
    """The block above is a full cube not in ``#does_not_block_hoppers``: no item entity is taken in."""
    if block.is_air or not block_shapes.is_collision_full(block):
        return False
    return not state.resources.in_tag("block", "minecraft:does_not_block_hoppers", block.id)


def _items_over(state, dimension, pos) -> list:
    """HopperBlockEntity.getItemsAtAndAbove: the living item entities touching the suck box."""
    x, y, z = pos
    box = (x, y + _SUCK_FLOOR, z, x + 1, y + 2, z + 1)
    return [e for e in state.entities.entities
            if e.alive and e.type == "minecraft:item" and e.dimension == dimension and _box_holds(e, box)]


def _take_entity(state, hopper: Target, entity, ticked: set) -> bool:
    """HopperBlockEntity.addItem(Container, ItemEntity): all of it in (the entity goes) or what is left."""
    slot = inventories.entity_slot(entity, 0, state.version)
    stack = slot.get()
    left = add_item(None, hopper, stack, None, ticked)
    if left.is_empty:
        slot.set(EMPTY.copy())
        state.discard(entity)
        return True
    if left.count != stack.count:
        slot.set(left)
    return False


def _suck(state, dimension, blocks, pos, hopper: Target, ticked: set) -> bool:
    above = (pos[0], pos[1] + 1, pos[2])
    source = container_at(state, dimension, blocks, above, "a hopper pulling items from")
    if source is not None:
        return any(not source.get(i).is_empty and source.can_take(i, source.get(i), "down")
                   and _one_out(source, i, hopper, None, ticked) for i in source.slots_for("down"))
    over = _items_over(state, dimension, pos)  # first: the shape above is asked only when it matters
    if not over or _blocks_hoppers(state, blocks.get(above)):
        return False
    return any(_take_entity(state, hopper, entity, ticked) for entity in over)


def transfer(state, dimension, blocks, pos, nbt, ticked: set) -> bool:
    """HopperBlockEntity.tryMoveItems: push, then pull; the cooldown 8 when anything moved."""
    if _properties(blocks.get(pos)).get("enabled") == "false":
        return False
    hopper = _hopper(state, blocks, pos, nbt)
    moved = False
    if not hopper.is_empty():
        moved = _eject(state, dimension, blocks, pos, hopper, ticked)
    if not _inventory_full(hopper):
        moved |= _suck(state, dimension, blocks, pos, hopper, ticked)
    if moved:
        nbt["TransferCooldown"] = Int(COOLDOWN)
    return moved


def minecart_would_pull(state) -> str | None:
    """What a hopper minecart would do that is not modelled (HopperMinecart.suckInItems: the
    container above it or the item entities around it), or None."""
    for cart in state.entities.minecarts():  # kept between entity changes: the common tick has none
        if not cart.alive or cart.type != "minecraft:hopper_minecart":
            continue
        x, y, z = cart.pos
        box = (x - 1.5, y - 0.5, z - 1.5, x + 1.5, y + 2, z + 1.5)
        above = (math.floor(x), math.floor(y) + 1, math.floor(z))
        if inventories.container(state.blocks_in(cart.dimension), above, state.version) is not None or any(
                e.alive and e.type == "minecraft:item" and e.dimension == cart.dimension and _box_holds(e, box)
                for e in state.entities.entities):
            return "a hopper minecart pulling items (what a hopper minecart does is not modelled)"
    return None


def still(state, dimension, blocks, pos, nbt) -> bool:
    """Whether :func:`transfer` would move nothing for certain: locked, or empty with nothing above
    to pull from (no container, composter or item entity there)."""
    if _properties(blocks.get(pos)).get("enabled") == "false":
        return True
    if nbt.get("Items"):
        return False
    x, y, z = pos
    above = blocks.get((x, y + 1, z))
    if above.id in _UNMODELLED:
        return False
    if above.id == composters.COMPOSTER:
        return composters.level(above) != composters.READY
    slots = inventories.container(blocks, (x, y + 1, z), state.version)
    if slots is not None and any(not slots.slot(i).get().is_empty for i in range(slots.size)):
        return False
    box = (x - 1, y, z - 1, x + 2, y + 3, z + 2)  # the suck box and the block above, with room to spare
    return not any(e.alive and e.dimension == dimension and (e.type == "minecraft:item" or e.type in
                   inventories.ENTITY_CONTAINERS) and _box_holds(e, box) for e in state.entities.entities)
