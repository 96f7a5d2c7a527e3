"""Advancements: each player's progress, granting and revoking, the criteria triggers the emulator
observes, and the rewards a completed advancement earns.

- Progress and reading it: :mod:`emulator.world.advancement_progress`.
- ``award(state, player, advancement_id, criterion) -> bool`` / ``revoke(...)``: PlayerAdvancements.
  award/revoke; completing an advancement queues its reward function on ``state.pending_rewards``
  (``(function id, player)``), which the backend running the command runs right after it, or the
  runtime at once outside commands (:func:`emulator.commands.advancements.earned_rewards`).
- ``related(resources, advancement_id, mode)``: the advancements ``only|from|until|through`` name.
- ``trigger(state, player, trigger, test=None)``: SimpleCriterionTrigger.trigger, the one entry
  for whatever fires a trigger (the actions' ``using_item``, ``consume_item`` ...):
  ``test(conditions, ctx)`` checks the trigger's own conditions. ``tick_players(state)``: the
  triggers a server tick fires for every player: the inventory's changes, ``tick`` each tick,
  ``location`` every 20 ticks of the player (counted from its first tick here).
- ``broadcast_changes(state, player)``: the inventory menu's changed slots fire
  ``inventory_changed`` (``inventory_changed(state, player, stack)``); the item commands call it
  where the game's do.
- ``item_picked_up(state, player, trigger, stack, entity)``: the thrown-item pickup triggers
  (:mod:`emulator.world.pickup`).
- ``entity_condition(state, condition, player, entity)``: a trigger's predicate about an entity.
- ``location_test(state, player, pos, stack)``: the location triggers' test (``item_used_on_block``,
  ``default_block_use``, ``placed_block``).

Sources (decompiled 1.21): server/PlayerAdvancements.java (award: rewards when the advancement
becomes done; revoke), advancements/AdvancementProgress.java and AdvancementRequirements.java
(done when every group has an obtained criterion; no requirements: never done),
advancements/AdvancementRewards.java (the function runs as the player, permission 2),
server/commands/AdvancementCommands.java (only/from/until/through/everything),
advancements/critereon/PlayerTrigger.java and SimpleCriterionTrigger.java (the ``player``
ContextAwarePredicate with the player as ``this`` at its position), server/level/ServerPlayer.java
(tick: broadcastChanges then the tick trigger; doTick: the location trigger every 20 ticks),
advancements/critereon/InventoryChangeTrigger.java,
world/inventory/AbstractContainerMenu.java (broadcastChanges, triggerSlotListeners),
world/inventory/InventoryMenu.java (slot order), commands/arguments/selector/options/
EntitySelectorOptions.java (``advancements``).
"""
from __future__ import annotations

from typing import Callable

from emulator.world import inside_blocks, inventories, living, loot, predicates, recipes
from emulator.world.advancement_progress import OBSERVED, full_id as _id, is_done, short_trigger
from emulator.world.entities import Entity
from emulator.world.errors import Unmodelled
from emulator.world.items import EMPTY, ItemStack
from emulator.world.loot_context import LootContext, in_ints
from mcfunction_parser.nbt import Compound, Int, IntArray, Short
from mcfunction_parser.pack.advancements import criteria

LOCATION_PERIOD = 20


def award(state, player: Entity, advancement_id: str, criterion: str) -> bool:
    """PlayerAdvancements.award: False when the criterion was already obtained; completing the
    advancement queues its reward function."""
    got = state.advancement_progress.of(player, advancement_id)
    if criterion in got:
        return False
    was_done = is_done(state, player, advancement_id)
    got.add(criterion)
    if not was_done and is_done(state, player, advancement_id):
        _reward(state, player, advancement_id)
    return True


def revoke(state, player: Entity, advancement_id: str, criterion: str) -> bool:
    got = state.advancement_progress.of(player, advancement_id)
    if criterion not in got:
        return False
    got.discard(criterion)
    return True


def _reward(state, player: Entity, advancement_id: str) -> None:
    """AdvancementRewards.grant, in its order: the experience points, each loot table's items, the
    recipes (ServerPlayer.awardRecipesByKey: an unknown one is skipped), then the function queued to
    run as the player."""
    rewards = state.resources.advancements[advancement_id].get("rewards") or {}
    if rewards.get("experience"):
        living.add_points(player, int(rewards["experience"]))
    try:
        _loot_rewards(state, player, rewards.get("loot") or [])
    except Unmodelled as reason:
        state.error(f"advancement {advancement_id}: its loot reward: {reason}", unmodelled=True)
    try:
        found = [r for r in map(_id, rewards.get("recipes") or []) if r and recipes.find(state.resources, r)]
        award_recipes(state, player, found)
    except Unmodelled as reason:
        state.error(f"advancement {advancement_id}: its recipes reward: {reason}", unmodelled=True)
    function = rewards.get("function")
    if isinstance(function, str):
        state.pending_rewards.append((function if ":" in function else "minecraft:" + function, player))


def _loot_rewards(state, player: Entity, tables: list) -> None:
    """Each table rolled with the player as ``this`` at its position (LootContextParamSets.
    ADVANCEMENT_REWARD); each stack into the inventory (Player.addItem), what is left of it thrown
    from the player (ServerPlayer.drop) with no pickup delay and the player as its target
    (``Owner``); the inventory menu broadcasts its changes once something went in. A table no pack
    defines drops nothing (LootTable.EMPTY)."""
    inventory, added = inventories.player_inventory(player, state.version), False
    ctx = LootContext(state, player.pos, this=player, dimension=player.dimension, random=state.resources.random)
    for table_id in tables:
        table_id = table_id if ":" in table_id else "minecraft:" + table_id
        for stack in loot.roll_table(state.resources.loot_table(table_id) or {}, ctx):
            if inventory.add(stack):  # true once all of it went in (Inventory.add)
                added = True
            elif not stack.is_empty:
                inventories.throw_from(state.entities, player, stack, state.version, state.resources.random,
                                       Compound(PickupDelay=Short(0), Owner=IntArray(Int(v) for v in player.uuid)))
    if added:
        broadcast_changes(state, player)


def award_recipes(state, player: Entity, recipe_ids: list[str]) -> int:
    """ServerPlayer.awardRecipes: the recipes added to the player's book, each firing
    ``recipe_unlocked`` (RecipeUnlockedTrigger: its ``recipe`` is the id); the number added."""
    def unlocked(recipe_id: str) -> None:
        trigger(state, player, "recipe_unlocked", lambda c, ctx: _id(c.get("recipe")) == recipe_id)
    return recipes.award(player, recipe_ids, state.resources, unlocked)


def related(resources, advancement_id: str, mode: str) -> list[str]:
    """AdvancementCommands.Mode: ``only`` the one, ``from`` it and its descendants, ``until`` it and
    its ancestors, ``through`` both; ``everything``: all."""
    every = resources.advancements
    if mode == "everything":
        return list(every)
    chosen = [advancement_id]
    if mode in ("until", "through"):
        parent = every[advancement_id].get("parent")
        while isinstance(parent, str) and parent in every and parent not in chosen:
            chosen.insert(0, parent)
            parent = every[parent].get("parent")
    if mode in ("from", "through"):
        frontier = [advancement_id]
        while frontier:
            current = frontier.pop(0)
            children = [a for a, body in every.items() if _id(body.get("parent")) == current and a not in chosen]
            chosen.extend(children)
            frontier.extend(children)
    return chosen


def warn_unobserved(state) -> None:
    """A warning per criterion whose trigger never fires here (its advancement only progresses by
    ``advancement grant``; reading its progress says it is not modelled)."""
    for advancement_id, advancement in state.resources.advancements.items():
        for name, criterion in criteria(advancement).items():
            if short_trigger(criterion["trigger"]) not in OBSERVED:
                state.error(f"advancement {advancement_id}: criterion '{name}' ({criterion['trigger']}) never fires "
                            "here: the emulator does not observe that trigger", severity="warning")


def tick_is_idle(state) -> bool:
    """Whether :func:`tick_players` would fire nothing now: no advancement, or no player."""
    return not state.resources.advancements or not state.entities.players()


def trigger(state, player: Entity, trigger: str, test: Callable[[dict, LootContext], bool] | None = None) -> None:
    """SimpleCriterionTrigger.trigger: every criterion of ``trigger`` (``minecraft:`` optional) that
    the player is listening for (PlayerAdvancements.registerListeners: the advancement is not done
    and the criterion not obtained) is awarded when its ``player`` predicate holds and
    ``test(conditions, ctx)`` accepts its conditions (``ctx``: the player as ``this`` at its
    position). The one entry for actions that fire a trigger."""
    trigger = short_trigger(trigger)
    for advancement_id, advancement in state.resources.advancements.items():
        if is_done(state, player, advancement_id):
            continue
        for name, criterion in criteria(advancement).items():
            if short_trigger(criterion["trigger"]) != trigger or name in state.advancement_progress.of(
                    player, advancement_id):
                continue
            ctx = LootContext(state, player.pos, this=player, dimension=player.dimension)
            if _player_matches(state, player, criterion) and (
                    test is None or test(criterion.get("conditions") or {}, ctx)):
                award(state, player, advancement_id, name)


def listened(state, trigger: str) -> bool:
    """Whether any loaded advancement has a criterion of ``trigger`` (else firing it changes nothing)."""
    return any(short_trigger(c["trigger"]) == trigger for a in state.resources.advancements.values()
               for c in criteria(a).values())


def tick_players(state) -> None:
    """ServerPlayer.tick: the inventory's changes are broadcast (inventory_changed), then ``tick``
    fires; then, in ServerPlayer.doTick, ``enter_block`` (aiStep) and ``location`` every 20 ticks
    of the player."""
    if not state.resources.advancements:
        return
    for player in state.entities.players():
        first = state.advancement_progress.first_tick.setdefault(player.uuid_string, state.tick)
        broadcast_changes(state, player)
        trigger(state, player, "tick")
        _levitation(state, player)
        _enter_block(state, player)
        if (state.tick - first) % LOCATION_PERIOD == 0:
            trigger(state, player, "location")


def _levitation(state, player: Entity) -> None:
    """ServerPlayer.tick after ``tick``: a player levitating since its onEffectAdded fires
    ``levitation`` with the distance from where it began and the ticks since (its tickCount has
    counted this tick); onEffectRemoved forgets the start."""
    start = player.levitation_start
    if start is None:
        return
    if living.effect_amplifier(player, living.LEVITATION) is None:
        player.levitation_start = None
        return
    origin, began = start
    duration = player.tick_count(state.tick) + 1 - began
    trigger(state, player, "levitation", lambda c, ctx: (
        (c.get("distance") is None or predicates.distance_matches(c["distance"], origin, player.pos))
        and (c.get("duration") is None or in_ints(c["duration"], duration))))


def _enter_block(state, player: Entity) -> None:
    """LivingEntity.aiStep (doTick, after ``tick``, before ``location``): ``enter_block`` for each
    block the player is inside (:mod:`emulator.world.inside_blocks`); EnterBlockTrigger.
    TriggerInstance.matches: the ``block`` (an id) and the ``state`` properties, each if given."""
    if not listened(state, "enter_block"):
        return
    try:
        for block in inside_blocks.entered(state, player, state.moves.get(player)):
            trigger(state, player, "enter_block", lambda c, ctx, block=block: (
                _id(c.get("block")) in (None, block.id)
                and predicates.state_matches(c.get("state"), block, state.version)))
    except Unmodelled as reason:
        state.unmodelled_once("advancement trigger enter_block", reason)


def changed_dimension(state, player: Entity, origin: str) -> None:
    """ServerPlayer.triggerDimensionChangeTriggers: ``changed_dimension`` with its ``from`` and
    ``to`` (ChangeDimensionTrigger.TriggerInstance.matches: a missing one matches any)."""
    def test(conditions: dict, ctx) -> bool:
        return all(conditions.get(key) in (None, level) for key, level in (("from", origin), ("to", player.dimension)))
    trigger(state, player, "changed_dimension", test)


def _player_matches(state, player: Entity, criterion: dict) -> bool:
    """The trigger's ``player`` predicate, the player as ``this`` at its position."""
    return entity_condition(state, (criterion.get("conditions") or {}).get("player"), player, player)


def location_test(state, player: Entity, pos, stack=None):
    """The ``location`` (and before 1.20 ``item``) conditions of ItemUsedOnLocationTrigger /
    DefaultBlockInteractionTrigger as a trigger test: loot conditions with the block's centre as
    origin, the player as ``this``, the block state at ``pos`` and the held stack as the tool."""
    origin = (pos[0] + 0.5, pos[1] + 0.5, pos[2] + 0.5)
    tool = stack if stack is not None and not stack.is_empty else None

    def test(conditions: dict, _ctx) -> bool:
        ctx = LootContext(state, origin, this=player, tool=tool, dimension=player.dimension,
                          block_state=state.blocks_in(player.dimension).get(pos))
        location = conditions.get("location")
        if isinstance(location, list):
            ok = predicates.test(location, ctx)
        else:
            ok = location is None or predicates.location_matches(location, ctx, origin)
        item = conditions.get("item")
        return ok and (item is None or predicates.item_matches(item, ctx, tool))
    return test


def entity_condition(state, condition, player: Entity, entity: Entity) -> bool:
    """A trigger's ContextAwarePredicate about ``entity`` (EntityPredicate.createContext: the entity
    as ``this``, the player's position as origin): loot conditions or an entity predicate; none
    holds."""
    if condition is None:
        return True
    ctx = LootContext(state, player.pos, this=entity, dimension=player.dimension)
    if isinstance(condition, list):
        return predicates.test(condition, ctx)
    return predicates.entity_matches(condition, ctx, entity)


# ---------------------------------------------------------------------- inventory_changed
# InventoryMenu's slots of the player's Inventory, in menu order: armor head..feet, the main
# inventory 9-35, the hotbar 0-8, the offhand (the crafting grid and result are other containers)
_MENU_SLOTS = (103, 102, 101, 100, *range(9, 36), *range(9), inventories.OFFHAND)
# Inventory.getItem(0..40): the main inventory, armor feet..head, the offhand
_INVENTORY_SLOTS = (*range(36), 100, 101, 102, 103, inventories.OFFHAND)


def broadcast_changes(state, player: Entity) -> None:
    """AbstractContainerMenu.broadcastChanges on the player's inventory menu: each slot whose stack
    differs from the last one seen (ItemStack.matches) fires inventory_changed with its new stack
    (ServerPlayer's slot listener). The game calls it each player tick and in give, clear, item and
    loot replace; ``loot give`` leaves it to the next tick."""
    if not listened(state, "inventory_changed"):
        return
    seen = state.advancement_progress.menu_slots.setdefault(player.uuid_string, {})
    for slot in _MENU_SLOTS:
        stack = inventories.entity_slot(player, slot, state.version).get()
        last = seen.get(slot, EMPTY)
        if not (stack.is_empty and last.is_empty or stack.count == last.count and stack.same_item_same_components(last)):
            seen[slot] = stack.copy()
            inventory_changed(state, player, stack)


def inventory_changed(state, player: Entity, stack: ItemStack) -> None:
    """InventoryChangeTrigger.trigger: the slot counts over the 41 slots of the Inventory (full: a
    stack at its maximum size), then each criterion's ``slots`` ranges and ``items``: none matches
    anything, one must match the changed stack (not empty), several must each match a different
    stack of the inventory (TriggerInstance.matches)."""
    stacks = [inventories.entity_slot(player, slot, state.version).get() for slot in _INVENTORY_SLOTS]
    occupied = [s for s in stacks if not s.is_empty]
    counts = {"occupied": len(occupied), "empty": len(stacks) - len(occupied),
              "full": sum(s.count >= s.max_stack_size for s in occupied)}
    def matches(conditions: dict, ctx: LootContext) -> bool:
        slots = conditions.get("slots") or {}
        if not all(in_ints(slots.get(key, {}), value) for key, value in counts.items()):
            return False
        wanted = conditions.get("items") or []
        if len(wanted) <= 1:
            return not wanted or not stack.is_empty and predicates.item_matches(wanted[0], ctx, stack)
        remaining = list(wanted)
        for found in occupied:
            remaining = [p for p in remaining if not predicates.item_matches(p, ctx, found)]
            if not remaining:
                return True
        return False
    trigger(state, player, "inventory_changed", matches)


# ---------------------------------------------------------------------- thrown items picked up
def item_picked_up(state, player: Entity, trigger_name: str, stack: ItemStack, entity: Entity) -> None:
    """PickedUpItemTrigger.trigger (``thrown_item_picked_up_by_player`` / ``_by_entity``): ``item``
    matches the stack, ``entity`` the other entity (EntityPredicate.createContext)."""
    def test(conditions: dict, ctx) -> bool:
        wanted = conditions.get("item")
        return ((wanted is None or predicates.item_matches(wanted, ctx, stack))
                and entity_condition(state, conditions.get("entity"), player, entity))
    trigger(state, player, trigger_name, test)


# ---------------------------------------------------------------------- effects_changed
def effects_changed(state, player: Entity, source: Entity | None) -> None:
    """EffectsChangedTrigger (ServerPlayer.onEffectAdded/onEffectUpdated/onEffectsRemoved): a
    player's effects were added, changed or removed. ``effects`` (MobEffectsPredicate) reads the
    effects the player has now; ``source`` is the entity that gave them (``effect give``'s
    executor; none for a removal, and then a ``source`` condition fails)."""
    if not player.is_player:
        return

    def matches(conditions: dict, ctx) -> bool:
        wanted = conditions.get("effects")
        if wanted is not None and not predicates.entity_matches({"effects": wanted}, ctx, player):
            return False
        if conditions.get("source") is None:
            return True
        return source is not None and entity_condition(state, conditions["source"], player, source)
    trigger(state, player, "effects_changed", matches)
