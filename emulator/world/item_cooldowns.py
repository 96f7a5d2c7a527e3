"""A player's item cooldowns (ItemCooldowns), as the ``use_cooldown`` component (1.21.2+) sets them:
while an item's cooldown group cools down, using an item of the group passes (nothing happens:
no ``using_item``, no statistic), and a block is used without it.

- ``on_cooldown(state, player, stack)``: ItemCooldowns.isOnCooldown.
- ``apply_use_cooldown(state, player, stack)``: UseCooldown.apply after a use that succeeded at once
  or a use that finished (ItemStack.applyAfterUseComponentSideEffects): the group cools down for
  Math.round(seconds * 20) ticks.
The group is the component's ``cooldown_group``, else the item's id (ItemCooldowns.getCooldownGroup);
the vanilla items that carry the component by default are the ender pearl, the chorus fruit and the
wind charge (before 1.21.2 the chorus fruit and the ender pearl cool down 20 ticks, in code). The player's tick count is the world's (both advance once a server tick).

Sources (decompiled 1.21.2+): world/item/ItemCooldowns.java (addCooldown, isOnCooldown,
getCooldownPercent, tick), world/item/component/UseCooldown.java, world/item/Items.java
(useCooldown), world/item/ItemStack.java (use, finishUsingItem, applyAfterUseComponentSideEffects),
server/level/ServerPlayerGameMode.java (useItem, useItemOn: the cooldown checks).
"""
from __future__ import annotations

import math

import numpy as np

from emulator.world.items import ItemStack
from emulator.world.nbt_ops import is_numeric, numeric_value
from mcfunction_parser.nbt import Compound

USE_COOLDOWN_VERSION = (1, 21, 2)
_VANILLA_SECONDS = {"minecraft:ender_pearl": 1.0, "minecraft:chorus_fruit": 1.0, "minecraft:wind_charge": 0.5}
_LEGACY = ("minecraft:chorus_fruit", "minecraft:ender_pearl")  # their 20-tick cooldown in code before 1.21.2


def _use_cooldown(state, stack: ItemStack) -> tuple[float, str] | None:
    """The stack's use_cooldown: (seconds, group); None without one."""
    if tuple(state.version) < USE_COOLDOWN_VERSION:  # ChorusFruitItem, EnderpearlItem: addCooldown(item, 20)
        return (1.0, stack.id) if stack.id in _LEGACY else None
    if "!minecraft:use_cooldown" in stack.patch:
        return None
    tag = stack.component("minecraft:use_cooldown")
    if isinstance(tag, Compound) and is_numeric(tag.get("seconds")):
        group = tag.get("cooldown_group")
        return float(numeric_value(tag["seconds"])), _group_id(str(group)) if group is not None else stack.id
    seconds = _VANILLA_SECONDS.get(stack.id)
    return (seconds, stack.id) if seconds is not None else None


def _group_id(text: str) -> str:
    return text if ":" in text else "minecraft:" + text


def _group(state, stack: ItemStack) -> str:
    found = _use_cooldown(state, stack)
    return found[1] if found is not None else stack.id


def on_cooldown(state, player, stack: ItemStack) -> bool:
    """ItemCooldowns.isOnCooldown: the group's cooldown ends after the player's current tick."""
    cooling = state.item_cooldowns.get(player)
    return bool(cooling) and cooling.get(_group(state, stack), -1) > state.tick


def apply_use_cooldown(state, player, stack: ItemStack) -> None:
    """UseCooldown.apply -> ItemCooldowns.addCooldown(group, Math.round(seconds * 20.0F))."""
    found = _use_cooldown(state, stack)
    if found is None:
        return
    seconds, group = found
    ticks = math.floor(float(np.float32(np.float32(seconds) * np.float32(20.0))) + 0.5)
    if ticks > 0:
        state.item_cooldowns.setdefault(player, {})[group] = state.tick + ticks
