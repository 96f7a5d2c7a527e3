"""Hanging entities check that they can stay: every 101 ticks an item frame that no longer survives
where it hangs breaks and drops (BlockAttachedEntity.tick, HangingEntity.tick before 1.21.2).

- ``tick_hanging(state)``: each hanging entity's tick; ``tick_is_idle(state)``: none hangs.

Each hanging entity counts its ticks from 0 (checkInterval, not saved: a frame loaded or summoned
starts again); on the tick its count reaches 100 it checks (:func:`emulator.world.frames.survives`)
and counts from 0 again. A frame that does not survive is removed and, with ``doEntityDrops``,
drops (ItemFrame.dropItem, spawnAtLocation at its position: pickup delay 10, random motion) its
frame item, then its item, whose ``ItemDropChance`` (1 unless set) is a chance: a value between 0
and 1 draws from the frame's own random, not modelled; 0 or less never drops it. A painting's check
(its size comes from its variant) and a leash knot's (its fence, the mobs it holds) are reported as
not modelled when they come.

Sources (decompiled 26.1.2 and 1.21.3: world/entity/decoration/BlockAttachedEntity.java (tick),
ItemFrame.java (survives, dropItem, getFrameItemStack), HangingEntity.java (survives);
1.20.6: HangingEntity.java (tick)).
"""
from __future__ import annotations

from emulator.world import frames, inventories
from emulator.world.errors import Unmodelled
from emulator.world.items import EMPTY, ItemStack, from_nbt
from emulator.world.nbt_ops import is_numeric, numeric_value

CHECK_AT = 100
HANGING = frozenset({*frames.FRAMES, "minecraft:painting", "minecraft:leash_knot"})


def _hanging(state) -> list:
    """The hanging entities, in the store's order (found again only when entities came or left)."""
    store = state.entities
    cached = state.hanging
    if cached[0] != store.changes or cached[1] is not store.entities:
        state.hanging = cached = (store.changes, store.entities, [e for e in store.entities if e.type in HANGING])
    return cached[2]


def tick_is_idle(state) -> bool:
    return not _hanging(state)


def tick_hanging(state) -> None:
    for entity in list(_hanging(state)):
        if not entity.alive:
            continue
        count = state.hanging_counts.get(entity, 0)
        state.hanging_counts[entity] = 0 if count == CHECK_AT else count + 1
        if count != CHECK_AT:
            continue
        try:
            _check(state, entity)
        except Unmodelled as reason:
            state.unmodelled_once("a hanging entity's check", reason)


def _check(state, entity) -> None:
    if entity.type not in frames.FRAMES:
        raise Unmodelled(f"whether a {entity.type} can stay (its variant's size or its fence)")
    face = frames.face_of(entity)
    if frames.survives(state, frames.block_of(entity), face, entity.dimension, bool(entity.data.get("Fixed", 0)),
                       itself=entity):
        return
    item = from_nbt(entity.data["Item"]) if "Item" in entity.data else EMPTY
    state.discard(entity)
    if state.gamerules.get("doEntityDrops") == "false":
        return
    _drop(state, entity, ItemStack(entity.type))
    if item.is_empty:
        return
    chance = entity.data.get("ItemDropChance")
    chance = float(numeric_value(chance)) if is_numeric(chance) else 1.0
    if 0.0 < chance < 1.0:
        raise Unmodelled("an item frame's item dropped by chance (ItemDropChance, the frame's random)")
    if chance >= 1.0:
        _drop(state, entity, item)


def _drop(state, entity, stack: ItemStack) -> None:
    inventories.drop_item(state.entities, entity.pos, stack, state.version, state.resources.random,
                          dimension=entity.dimension)
