"""A player picking up an item entity it touches (ItemEntity.playerTouch), called from the item's
tick when its pickup delay is 0 (:mod:`emulator.world.motion`).

- ``player_touch(state, player, item)``: the item's stack goes into the player's inventory as far
  as it fits (Inventory.add: onto stacks with room, then into free slots, pass after pass; a
  damaged item only into a free slot; a creative player's takes everything). What went in is
  gone from the item entity (the stack Inventory.add shrinks is the entity's own). Inventory.add
  answers true only when it took everything (its last pass moved nothing otherwise, and it
  compares with that pass): only then is the item entity gone, the player's
  ``minecraft.picked_up:<item>`` counts the whole stack, and onItemPickup follows: with a thrower
  (``Thrower``, an entity of the item's level) the player fires ``thrown_item_picked_up_by_player``
  (the thrower as ``entity``) and a thrower that is a player fires
  ``thrown_item_picked_up_by_entity`` (the picker as ``entity``), both with the item's stack (its
  whole count when it was emptied). The inventory's change fires ``inventory_changed`` at the
  player's tick (:func:`emulator.world.advancements.broadcast_changes`).

Sources (decompiled 1.21): world/entity/item/ItemEntity.java (playerTouch, getOwner),
world/entity/player/Inventory.java (add, addResource), world/entity/LivingEntity.java and
server/level/ServerPlayer.java (onItemPickup), advancements/critereon/PickedUpItemTrigger.java.
"""
from __future__ import annotations

from emulator.world import advancements, inventories, items, relations, statistics


def player_touch(state, player, item) -> None:
    """ItemEntity.playerTouch for an item with no pickup delay and no other owner."""
    stack = items.from_nbt(item.data.get("Item"))
    count, item_id = stack.count, stack.id
    taken = inventories.player_inventory(player, state.version).add(stack)
    if 0 < stack.count < count:  # the stack Inventory.add shrank is the entity's own, whatever it answers
        item.data["Item"] = items.to_nbt(stack, state.version)
    if not taken:
        return
    if stack.is_empty:
        state.discard(item)  # discard
        stack.count = count
    statistics.award(state, player, statistics.stat_name("picked_up", item_id), count)
    _on_item_pickup(state, player, item, stack)


def _on_item_pickup(state, player, item, stack) -> None:
    """LivingEntity/ServerPlayer.onItemPickup: the thrown-item triggers, when the thrower is there
    (ItemEntity.getOwner, as ``execute on origin`` reads it, in the item's level)."""
    for thrower in relations.related(state, item, "origin"):
        if thrower.dimension != item.dimension:
            continue
        if thrower.is_player:
            advancements.item_picked_up(state, thrower, "thrown_item_picked_up_by_entity", stack, player)
        advancements.item_picked_up(state, player, "thrown_item_picked_up_by_player", stack, thrower)
