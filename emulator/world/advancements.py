"""Advancements: each player's progress, granting and revoking, the criteria triggers the emulator
observes, and the rewards a completed advancement earns.

- Progress and reading it: :mod:`emulator.world.advancement_progress`.
- ``award(state, player, advancement_id, criterion) -> bool`` / ``revoke(...)``: PlayerAdvancements.
  award/revoke; completing an advancement queues its reward function on ``state.pending_rewards``
  (``(function id, player)``), which the runtime runs as the player.
- ``related(resources, advancement_id, mode)``: the advancements ``only|from|until|through`` name.
- ``tick_players(state)``: the triggers a server tick fires for every player: ``tick`` each tick,
  ``location`` every 20 ticks of the player (counted from its first tick here).
- ``trigger(state, player, trigger, test=None)``: SimpleCriterionTrigger.trigger: every criterion of
  that trigger the player has not obtained, whose ``player`` predicate holds and whose other
  conditions ``test(conditions, ctx)`` accepts, is awarded (the actions' triggers: ``using_item``,
  ``player_hurt_entity`` ...).

Sources (decompiled 1.21): server/PlayerAdvancements.java (award: rewards when the advancement
becomes done; revoke), advancements/AdvancementProgress.java and AdvancementRequirements.java
(done when every group has an obtained criterion; no requirements: never done),
advancements/AdvancementRewards.java (the function runs as the player, permission 2),
server/commands/AdvancementCommands.java (only/from/until/through/everything),
advancements/critereon/PlayerTrigger.java and SimpleCriterionTrigger.java (the ``player``
ContextAwarePredicate with the player as ``this`` at its position), server/level/ServerPlayer.java
(doTick: the location trigger every 20 ticks), commands/arguments/selector/options/
EntitySelectorOptions.java (``advancements``).
"""
from __future__ import annotations

from emulator.world import predicates
from emulator.world.advancement_progress import OBSERVED, full_id as _id, is_done, short_trigger
from emulator.world.entities import Entity
from emulator.world.loot_context import LootContext
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
    rewards = state.resources.advancements[advancement_id].get("rewards") or {}
    function = rewards.get("function")
    if isinstance(function, str):
        state.pending_rewards.append((function if ":" in function else "minecraft:" + function, player))
    for kind in ("experience", "loot", "recipes"):
        if rewards.get(kind):
            state.error(f"advancement {advancement_id}: the {kind} reward is not modelled", severity="warning",
                        unmodelled=True)


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


def tick_players(state) -> None:
    """The triggers each player fires in its tick: ``tick``, and ``location`` every 20 ticks."""
    if not state.resources.advancements:
        return
    for player in state.entities.players():
        first = state.advancement_progress.first_tick.setdefault(player.uuid_string, state.tick)
        fired = {"tick"} | ({"location"} if (state.tick - first) % LOCATION_PERIOD == 0 else set())
        for advancement_id, advancement in state.resources.advancements.items():
            for name, criterion in criteria(advancement).items():
                if short_trigger(criterion["trigger"]) in fired and name not in state.advancement_progress.of(
                        player, advancement_id) and _player_matches(state, player, criterion):
                    award(state, player, advancement_id, name)


def trigger(state, player: Entity, trigger_name: str, test=None) -> None:
    """SimpleCriterionTrigger.trigger for one player: ``test(conditions, ctx)`` checks the
    trigger's own conditions (the player as ``this`` at its position in ``ctx``)."""
    for advancement_id, advancement in state.resources.advancements.items():
        got = state.advancement_progress.of(player, advancement_id)
        for name, criterion in criteria(advancement).items():
            if short_trigger(criterion["trigger"]) != trigger_name or name in got:
                continue
            ctx = predicates.LootContext(state, player.pos, this=player, dimension=player.dimension)
            if _player_matches(state, player, criterion) and (
                    test is None or test(criterion.get("conditions") or {}, ctx)):
                award(state, player, advancement_id, name)


def changed_dimension(state, player: Entity, origin: str) -> None:
    """ServerPlayer.triggerDimensionChangeTriggers: ``changed_dimension`` with its ``from`` and
    ``to`` (ChangeDimensionTrigger.TriggerInstance.matches: a missing one matches any)."""
    def test(conditions: dict, ctx) -> bool:
        return all(conditions.get(key) in (None, level) for key, level in (("from", origin), ("to", player.dimension)))
    trigger(state, player, "changed_dimension", test)


def _player_matches(state, player: Entity, criterion: dict) -> bool:
    """The trigger's ``player`` predicate, the player as ``this`` at its position."""
    condition = (criterion.get("conditions") or {}).get("player")
    if condition is None:
        return True
    ctx = LootContext(state, player.pos, this=player, dimension=player.dimension)
    if isinstance(condition, list):
        return predicates.test(condition, ctx)
    return predicates.entity_matches(condition, ctx, player)
