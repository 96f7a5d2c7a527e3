"""What a player does with its hands, as the server carries it out: dropping the held stack,
swapping hands, using the held item (and the ticks of using it), with what a datapack observes of
each (the item entity, the inventory NBT, statistics, the ``using_item``/``consume_item`` criteria).

- ``drop_selected(state, player, whole)``: ServerPlayer.drop(boolean): one item (or the whole
  stack) out of the selected hotbar slot as an item entity thrown by the player; None when the hand
  is empty.
- ``swap_hands(state, player)``: the main hand and offhand stacks trade places.
- ``filled_result(state, player, empty, filled)``: ItemUtils.createFilledResult: what the hand
  holds after filling one of its containers (a bucket milked, filled at a cauldron ...).
- ``use_item(state, player, hand)``: ServerPlayerGameMode.useItem (an item whose cooldown group
  cools down passes: emulator.world.item_cooldowns) -> Item.use for the items whose use is modelled (:data:`USES`, and what emulator.world.consumables says is eaten or drunk: its
  food, effects and use remainder); returns ``"consume"``, ``"pass"`` or ``"fail"`` (InteractionResult:
  only ``consume`` is an action the client's use stops at). Any other item raises Unmodelled.
- ``tick_using(state)``: each player using an item (LivingEntity.updatingUsingItem): the
  ``using_item`` trigger every tick, and when its use duration ends the item is consumed.

Sources (decompiled 1.21.x): server/level/ServerPlayer.java (drop, updateUsingItem),
world/entity/player/Player.java and LivingEntity.java (createItemStackToDrop, startUsingItem,
updatingUsingItem, completeUsingItem), world/entity/player/Inventory.java (removeFromSelected),
server/level/ServerPlayerGameMode.java (useItem), world/item/FoodOnAStickItem.java,
KnowledgeBookItem.java, Item.java (use), world/item/component/Consumable.java (startConsuming,
onConsume, consumeTicks), world/food/FoodData.java (eat), world/food/FoodProperties.java,
world/item/ItemStack.java (finishUsingItem, applyAfterUseComponentSideEffects), UseRemainder.java
(convertIntoRemainder), ServerPlayer.handleExtraItemsCreatedOnUse, consume_effects/*.java.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from emulator.world import (advancements, combat, consumables, consume_effects, inventories, item_cooldowns, living,
                            predicates, projectile_weapons, random_teleport, recipes, statistics, tools)
from emulator.world.errors import Unmodelled
from emulator.world.items import ItemStack, enchantment_level
from emulator.world.nbt_ops import is_numeric, numeric_value
from mcfunction_parser.nbt import Compound, Int, IntArray

F32 = np.float32
MAIN, OFF = "main_hand", "off_hand"
BOW_USE_TICKS = 72000  # BowItem.getUseDuration
CROSSBOW_USE_TICKS = 28  # CrossbowItem.getUseDuration: the charge duration (25 ticks) + 3


# ---------------------------------------------------------------------- drop and swap
def drop_selected(state, player, whole: bool):
    """ServerPlayer.drop(boolean): Inventory.removeFromSelected (one item, or the stack), thrown
    from the eyes (minus 0.3) with a pickup delay of 40 and the player as ``Thrower``; awards
    ``minecraft.dropped:<item>`` (the count) and ``minecraft.custom:minecraft.drop``."""
    version = state.version
    access = inventories.entity_slot(player, inventories.MAINHAND, version)
    held = access.get()
    if held.is_empty:
        return None
    taken = held.copy()
    taken.count = held.count if whole else 1
    held.count -= taken.count
    access.set(held)
    entity = _throw(state, player, taken, thrown_from_hand=True)
    statistics.award(state, player, statistics.stat_name("dropped", taken.id), taken.count)
    statistics.award(state, player, statistics.stat_name("custom", "drop"))
    return entity


def drop_from(state, player, stack: ItemStack):
    """ServerPlayer.drop(stack, false, false): the stack thrown from the eyes, no thrower, no statistic."""
    return _throw(state, player, stack, thrown_from_hand=False)


def _throw(state, player, stack: ItemStack, thrown_from_hand: bool):
    """LivingEntity.createItemStackToDrop (not randomly): :func:`inventories.throw_from`, the
    player as ``Thrower`` when thrown from the hand."""
    extra = Compound(Thrower=IntArray(Int(v) for v in player.uuid)) if thrown_from_hand else None
    return inventories.throw_from(state.entities, player, stack, state.version, state.resources.random, extra)


def filled_result(state, player, empty: ItemStack, filled: ItemStack) -> ItemStack:
    """ItemUtils.createFilledResult(empty, player, filled, true): what the hand holds after filling."""
    inventory = inventories.player_inventory(player, state.version)
    if player.gamemode == "creative":
        if not inventory.clear_or_count(lambda s: s.same_item_same_components(filled), 0):  # Inventory.contains
            inventory.add(filled)
        return empty
    empty.count -= 1
    if empty.is_empty:
        return filled
    if not inventory.add(filled):  # Inventory.add moved nothing
        drop_from(state, player, filled)
    return empty


def swap_hands(state, player) -> None:
    """PackTest's swap (setItemInHand both ways): main hand and offhand trade their stacks."""
    main, off = (inventories.entity_slot(player, s, state.version) for s in (inventories.MAINHAND, inventories.OFFHAND))
    held, other = main.get(), off.get()
    off.set(held)
    main.set(other)


# ---------------------------------------------------------------------- using items
@dataclass
class _Using:
    hand: str
    item: str  # the used item's id (LivingEntity.useItem; ItemStack.isSameItem compares the item only)
    remaining: int  # useItemRemaining


def hand_slot(hand: str) -> int:
    return inventories.MAINHAND if hand == MAIN else inventories.OFFHAND


def use_item(state, player, hand: str) -> str:
    """ServerPlayerGameMode.useItem with the stack in ``hand``: a spectator passes; else Item.use."""
    if player.gamemode == "spectator":
        return "pass"
    stack = inventories.entity_slot(player, hand_slot(hand), state.version).get()
    if stack.is_empty:
        return "pass"  # Items.AIR: Item.use passes
    if item_cooldowns.on_cooldown(state, player, stack):
        return "pass"
    consumable = consumables.consumable(stack, state.version)
    if consumable is not None:
        return _start_consuming(state, player, hand, stack, consumable)
    use = USES.get(stack.id)
    if use is None:
        raise Unmodelled(f"using {stack.id} (its right-click behaviour is not modelled: only "
                         f"{', '.join(sorted(USES))} and items with a consumable or food component)")
    return use(state, player, hand, stack)


def _food_on_a_stick(state, player, hand, stack: ItemStack) -> str:
    """FoodOnAStickItem.use: not riding what it steers, it counts ``minecraft.used`` and passes."""
    if player.vehicle is not None:
        raise Unmodelled(f"using {stack.id} while riding (steering a pig or strider)")
    statistics.award(state, player, statistics.stat_name("used", stack.id))
    return "pass"


def _knowledge_book(state, player, hand, stack: ItemStack) -> str:
    """KnowledgeBookItem.use: the book is consumed (not in creative); with no recipes it fails, as
    it does when one of them does not exist (logged "Invalid recipe"); else the player learns them
    all (ServerPlayer.awardRecipes), ``minecraft.used:knowledge_book`` counts and the use consumes
    the action. The recipes are the ``recipes`` component (``Recipes`` in the tag before 1.20.5)."""
    listed = stack.component("minecraft:recipes") or (stack.tag or {}).get("Recipes") or []
    names = [str(r) if ":" in str(r) else "minecraft:" + str(r) for r in listed]
    _consume_one(state, player, hand)
    if not names or not all(recipes.find(state.resources, r) for r in names):
        return "fail"
    advancements.award_recipes(state, player, names)
    statistics.award(state, player, statistics.stat_name("used", stack.id))
    return "consume"


def _bow(state, player, hand, stack: ItemStack) -> str:
    """BowItem.use: with ammunition (or in creative) the bow is drawn for 72000 ticks (getUseDuration);
    it shoots only when released, which a dummy never does."""
    if player.gamemode != "creative" and projectile_weapons.ammunition(state, player, stack).is_empty:
        return "fail"
    state.using_items[player] = _Using(hand, stack.id, BOW_USE_TICKS)
    return "consume"


def _crossbow(state, player, hand, stack: ItemStack) -> str:
    """CrossbowItem.use: a charged crossbow shoots at once; else with ammunition it starts charging,
    which completes only on release (never for a dummy)."""
    if projectile_weapons.charged(stack):
        projectile_weapons.shoot_charged(state, player, hand_slot(hand))
        return "consume"
    if projectile_weapons.ammunition(state, player, stack).is_empty:
        return "fail"
    state.using_items[player] = _Using(hand, stack.id, CROSSBOW_USE_TICKS)
    return "consume"


def _throwable(state, player, hand, stack: ItemStack) -> str:
    """SnowballItem, EggItem, EnderpearlItem, ThrowablePotionItem, ExperienceBottleItem.use: the item
    is thrown (:func:`emulator.world.projectile_weapons.throw`), ``minecraft.used:<item>``, one
    consumed (not in creative), an ender pearl's cooldown (20 ticks; from 1.21.2 its use_cooldown
    component after the use: ItemStack.applyAfterUseComponentSideEffects); the use succeeds."""
    before = stack.copy()
    projectile_weapons.throw(state, player, stack)
    statistics.award(state, player, statistics.stat_name("used", stack.id))
    _consume_one(state, player, hand)
    item_cooldowns.apply_use_cooldown(state, player, before)
    return "consume"


def _trident(state, player, hand, stack: ItemStack) -> str:
    """TridentItem.use: too damaged to use (one point from breaking) or with Riptide out of water and
    rain it fails; else it is drawn for 72000 ticks and thrown only when released, which a dummy
    never does (as a bow)."""
    components = tuple(state.version) >= tools.COMPONENTS_VERSION
    damage = stack.component("minecraft:damage") if components else (stack.tag or {}).get("Damage")
    max_damage = stack.component("minecraft:max_damage")
    if is_numeric(max_damage) and (int(numeric_value(damage)) if is_numeric(damage) else 0) >= \
            int(numeric_value(max_damage)) - 1:  # isTooDamagedToUse
        return "fail"
    if enchantment_level(stack, "minecraft:riptide") > 0:
        raise Unmodelled("using a trident with Riptide (in water or rain it launches the player)")
    state.using_items[player] = _Using(hand, stack.id, BOW_USE_TICKS)
    return "consume"


USES = {"minecraft:carrot_on_a_stick": _food_on_a_stick, "minecraft:warped_fungus_on_a_stick": _food_on_a_stick,
        "minecraft:knowledge_book": _knowledge_book, "minecraft:bow": _bow, "minecraft:crossbow": _crossbow,
        "minecraft:trident": _trident, **dict.fromkeys(projectile_weapons.THROWS, _throwable)}


def _start_consuming(state, player, hand: str, stack: ItemStack, consumable: consumables.Consumable) -> str:
    """Consumable.startConsuming: a food the player cannot eat fails; a duration starts using the
    item, none consumes it at once."""
    if consumable.food is not None and not _can_eat(player, consumable.food):
        return "fail"
    unmodelled = consume_effects.unmodelled(consumable.effects)
    if unmodelled:  # known when the use starts, so the dummy's command is what the test reports
        raise Unmodelled(f"the {unmodelled} consume effect of {stack.id}")
    if consumable.ticks > 0:
        state.using_items[player] = _Using(hand, stack.id, consumable.ticks)
        return "consume"
    _finish(state, player, hand, consumable)  # ItemStack.use: at once, then its cooldown (in _finish)
    return "consume"


def _can_eat(player, food: consumables.Food) -> bool:
    """Player.canEat: invulnerable (creative), food that can always be eaten, or hunger below 20."""
    return (player.gamemode == "creative" or food.can_always_eat
            or int(numeric_value(player.data.get("foodLevel", Int(20)))) < 20)


def tick_is_idle(state) -> bool:
    """Whether :func:`tick_using` would do nothing now: no player is using an item."""
    return not state.using_items


def tick_using(state) -> None:
    """LivingEntity.updatingUsingItem for each player using an item: stops when the hand no longer
    holds that item; else ``using_item`` fires (ServerPlayer.updateUsingItem) and, when the duration
    runs out, the item is consumed (completeUsingItem)."""
    if not state.using_items:  # every tick: nobody using an item is the common case
        return
    for player, using in list(state.using_items.items()):
        if not player.alive:
            del state.using_items[player]
            continue
        stack = inventories.entity_slot(player, hand_slot(using.hand), state.version).get()
        if stack.is_empty or stack.id != using.item:
            del state.using_items[player]
            continue
        advancements.trigger(state, player, "using_item", _item_test(state, stack))
        using.remaining -= 1
        if using.remaining == 0 and stack.id != "minecraft:crossbow":  # Item.useOnRelease: a crossbow waits
            del state.using_items[player]
            consumable = consumables.consumable(stack, state.version)
            if consumable is not None:
                _finish(state, player, using.hand, consumable)


def _finish(state, player, hand: str, consumable: consumables.Consumable) -> None:
    """ItemStack.finishUsingItem -> Consumable.onConsume: ``minecraft.used:<item>`` and
    ``consume_item`` with the stack before it shrinks, the listeners (the food eaten, a potion's or
    stew's effects), the consume effects, one item consumed (not in creative), then the use
    remainder (UseRemainder.convertIntoRemainder: the emptied hand holds it, else it goes to the
    inventory or is dropped)."""
    access = inventories.entity_slot(player, hand_slot(hand), state.version)
    stack = access.get()
    before = stack.copy()
    statistics.award(state, player, statistics.stat_name("used", stack.id))
    advancements.trigger(state, player, "consume_item", _item_test(state, stack))
    if consumable.food is not None:
        living.eat(player, consumable.food.nutrition, consumable.food.saturation)
    harm = _self_harm(player)
    consume_effects.give_effects(state, player, consumable.gives, harm)
    consume_effects.apply(state, player, consumable.effects, harm, random_teleport.teleport_randomly,
                          consumable.per_effect_draw)
    if player.gamemode != "creative":  # hasInfiniteMaterials: nothing shrinks, no remainder
        _consume_one(state, player, hand)
        if consumable.remainder is not None and before.count > 0:
            _give_remainder(state, player, access, consumable.remainder.copy())
    item_cooldowns.apply_use_cooldown(state, player, before)  # applyAfterUseComponentSideEffects


def _self_harm(player):
    """A potion's instant harm as indirect magic from the player who drank it."""
    def harm(state, entity, amount: float) -> bool:
        return combat.hurt(state, entity, amount, combat.DamageSource("minecraft:indirect_magic", player, player))
    return harm


def _give_remainder(state, player, access, remainder: ItemStack) -> None:
    """UseRemainder.convertIntoRemainder; ServerPlayer.handleExtraItemsCreatedOnUse."""
    if access.get().is_empty:
        access.set(remainder)
        return
    if not inventories.player_inventory(player, state.version).add(remainder) or not remainder.is_empty:
        drop_from(state, player, remainder)


def _consume_one(state, player, hand: str) -> None:
    """ItemStack.consume(1, entity): shrinks unless the player has infinite materials (creative)."""
    if player.gamemode == "creative":
        return
    access = inventories.entity_slot(player, hand_slot(hand), state.version)
    stack = access.get()
    stack.count -= 1
    access.set(stack)


def _item_test(state, stack: ItemStack):
    """The ``item`` condition of the using_item / consume_item criteria (an ItemPredicate)."""
    def test(conditions: dict, ctx) -> bool:
        wanted = conditions.get("item")
        return wanted is None or predicates.item_matches(wanted, ctx, stack)
    return test
