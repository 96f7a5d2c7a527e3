"""Advancement triggers fired by the world (emulator.world.advancements), each pinned to its source
(decompiled 1.21: advancements/critereon/*Trigger.java, server/PlayerAdvancements.java)."""
from __future__ import annotations

from emulator.world import advancements, inventories
from emulator.world.items import ItemStack
from emulator.world.resources import Resources
from emulator.world.state import WorldState


def _world(**bodies) -> tuple[WorldState, object]:
    state = WorldState(resources=Resources(advancements={f"t:{k}": v for k, v in bodies.items()}))
    return state, state.entities.add_player("Alex", (0.0, 64.0, 0.0))


def _has(state, player, advancement, criterion) -> bool:
    return criterion in state.advancement_progress.of(player, f"t:{advancement}")


def test_a_done_advancement_listens_no_more():
    # PlayerAdvancements.registerListeners: a done advancement's criteria are not listened for, so
    # the criterion left over in a one-of requirement is never obtained after it
    either = {"criteria": {"a": {"trigger": "minecraft:tick"}, "b": {"trigger": "minecraft:inventory_changed"}},
              "requirements": [["a", "b"]]}
    state, player = _world(either=either)
    advancements.trigger(state, player, "tick")
    advancements.inventory_changed(state, player, ItemStack("minecraft:stone"))
    assert _has(state, player, "either", "a") and not _has(state, player, "either", "b")


def test_inventory_changed_counts_the_slots():
    # InventoryChangeTrigger.trigger: over the 41 slots of the Inventory, full is a stack at its
    # maximum size; the ranges are MinMaxBounds.Ints
    full = {"criteria": {"x": {"trigger": "minecraft:inventory_changed",
                               "conditions": {"slots": {"full": 1, "empty": 39, "occupied": {"min": 2}}}}}}
    state, player = _world(full=full)
    inventories.entity_slot(player, 0, state.version).set(ItemStack("minecraft:ender_pearl", 16))
    inventories.entity_slot(player, inventories.OFFHAND, state.version).set(ItemStack("minecraft:stone", 3))
    advancements.broadcast_changes(state, player)
    assert _has(state, player, "full", "x")
