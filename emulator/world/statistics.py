"""Player statistics as scoreboard criteria: ``Player.awardStat`` adds to every objective whose
criterion is that statistic (``minecraft.custom:minecraft.jump``, ``minecraft.used:minecraft.
carrot_on_a_stick`` ...), for the player's name, creating the score at 0 first.

- ``stat_name(kind, value)``: the statistic's criterion name, ``minecraft.<kind>:<ns>.<path>``.
- ``canonical_criterion(text)``: a criterion as ``ObjectiveCriteria.byName`` reads it: the stat type
  and the value are resource locations written with ``.`` for ``:``, so ``custom:jump`` and
  ``minecraft.custom:minecraft.jump`` name the same statistic; other criteria come back unchanged.
- ``award(state, player, stat, amount=1)``: ``Player.awardStat`` for the player entity;
  ``reset(state, player, stat)``: ``ServerPlayer.resetStat`` (the score is reset from 1.20.3,
  set to 0 before).
- ``tick_players(state)``: the statistics every player earns each tick (``Player.tick``, server side:
  play_time, total_world_time, time_since_death, sneak_time while the sneak key is held,
  time_since_rest); the game ticks players after the tick's functions and scheduled functions.

The statistics counter itself (``ServerStatsCounter``) is not kept: an objective created after a
player earned a statistic starts empty for that player, as in the game, so only the scores matter.

Sources (decompiled 1.21): world/scores/criteria/ObjectiveCriteria.java (byName, getName),
stats/StatType.java, world/entity/player/Player.java (awardStat, tick, jumpFromGround),
server/level/ServerPlayer.java (awardStat -> Scoreboard.forAllObjectives ... ScoreAccess.add).
"""
from __future__ import annotations

from emulator.world.semantics import wrap32

STAT_TYPES = ("custom", "mined", "crafted", "used", "broken", "picked_up", "dropped", "killed", "killed_by")
# Player.tick's statistics (server side) of a living player who is not sleeping
PER_TICK = ("play_time", "total_world_time", "time_since_death", "time_since_rest")
RESET_UNSETS = (1, 20, 3)  # ScoreAccess::reset (23w46a) replaced Score::reset, which set 0
SNEAK_TIME = "sneak_time"  # Stats.CROUCH_TIME: while isDiscrete(), i.e. the sneak key is held


def _location(text: str) -> str:
    """``ResourceLocation.tryBySeparator(text, '.')``: ``ns.path`` or ``path`` (namespace minecraft)."""
    namespace, dot, path = text.partition(".")
    return f"{namespace}:{path}" if dot else f"minecraft:{text}"


def canonical_criterion(text: str) -> str:
    """The criterion's name as the game prints it (``minecraft.used:minecraft.stick``)."""
    kind, colon, value = text.partition(":")
    if not colon:
        return text
    kind_id, value_id = _location(kind), _location(value)
    if kind_id.split(":", 1)[1] not in STAT_TYPES or not kind_id.startswith("minecraft:"):
        return text
    return f"{kind_id.replace(':', '.')}:{value_id.replace(':', '.', 1)}"


def stat_name(kind: str, value: str) -> str:
    """``stat_name("custom", "jump")`` -> ``minecraft.custom:minecraft.jump``."""
    value_id = value if ":" in value else f"minecraft:{value}"
    return f"minecraft.{kind}:{value_id.replace(':', '.', 1)}"


def award(state, player, stat: str, amount: int = 1) -> None:
    """Add ``amount`` to the player's score on every objective counting ``stat``."""
    board = state.scoreboard
    for name in board.objectives:
        oid = board.objective_ids[name]
        if board.alive[oid] and canonical_criterion(board.criteria[oid]) == stat:
            current = board.get(player.score_holder, name) or 0
            board.set(player.score_holder, name, wrap32(current + amount))


def reset(state, player, stat: str) -> None:
    board = state.scoreboard
    for name in board.objectives:
        oid = board.objective_ids[name]
        if board.alive[oid] and canonical_criterion(board.criteria[oid]) == stat:
            if tuple(state.version) >= RESET_UNSETS:
                board.reset(player.score_holder, name)
            else:
                board.set(player.score_holder, name, 0)


def tick_players(state) -> None:
    """Each living player's per-tick statistics, after the tick's functions ran."""
    if not _counts_statistics(state.scoreboard):
        return  # no statistic objective: nothing to count (the common case, kept cheap)
    for player in state.entities.players():
        for stat in PER_TICK:
            if stat != "time_since_death" or player.alive:  # Player.tick: only while alive
                award(state, player, stat_name("custom", stat))
        if player.sneaking:
            award(state, player, stat_name("custom", SNEAK_TIME))


def tick_is_idle(state) -> bool:
    """Whether :func:`tick_players` would change nothing now: no statistic objective, or no player."""
    return not _counts_statistics(state.scoreboard) or not state.entities.players()


def _counts_statistics(board) -> bool:
    return bool(board.statistic_ids) and any(board.alive[oid] for oid in board.statistic_ids)
