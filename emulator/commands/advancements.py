"""``advancement grant|revoke TARGETS everything|only ADV [CRITERION]|from ADV|until ADV|through ADV``,
and the reward functions earned (:func:`earned_rewards`), which the backends run.

The parser keeps the command as text; it is read here. Sources (decompiled 1.21):
server/commands/AdvancementCommands.java (perform / performCriterion: the result is the number of
(player, advancement) pairs changed, none fails with the one/many messages; GRANT awards every
remaining criterion, REVOKE revokes every obtained one), EntityArgument.getPlayers.
"""
from __future__ import annotations

from emulator.world import advancement_progress, advancements
from emulator.world.advancement_progress import is_done
from mcfunction_parser.pack.advancements import criteria
from emulator.world.errors import CommandFailure
from mcfunction_parser import ast, selectors
from mcfunction_parser.arguments import holder_from_word
from mcfunction_parser.reader import ParseError, Reader

from .entities import entity_context, select

_MODES = ("only", "from", "until", "through")


def advancement(env, cmd: ast.GenericCommand, ctx) -> int:
    action, targets, mode, advancement_id, criterion = _read(cmd)
    state = env.state
    players = select(state, targets, ctx)
    if any(not p.is_player for p in players):
        raise CommandFailure("argument.player.entities", report=True)
    if not players:
        raise CommandFailure("argument.entity.notfound.player")
    known = state.resources.advancements
    if advancement_id is not None and not advancement_progress.known(state, advancement_id):
        raise CommandFailure("advancement.advancementNotFound", advancement_id, report=True)
    change = advancements.award if action == "grant" else advancements.revoke
    if criterion is not None:
        if criterion not in criteria(known[advancement_id]):
            raise CommandFailure("commands.advancement.criterionNotFound", f"[{advancement_id}]", criterion)
        changed = sum(change(state, p, advancement_id, criterion) for p in players)
        if changed == 0:
            many = "many" if len(players) > 1 else "one"
            raise CommandFailure(f"commands.advancement.{action}.criterion.to.{many}.failure", criterion,
                                 f"[{advancement_id}]", len(players) if many == "many" else players[0].display_name)
        return changed
    chosen = advancements.related(state.resources, advancement_id, mode)
    changed = sum(_perform(state, action, p, a) for p in players for a in chosen)
    if changed == 0:
        first = "many" if len(chosen) != 1 else "one"
        second = "many" if len(players) > 1 else "one"
        what = len(chosen) if first == "many" else f"[{chosen[0]}]"
        who = len(players) if second == "many" else players[0].display_name
        raise CommandFailure(f"commands.advancement.{action}.{first}.to.{second}.failure", what, who)
    return changed


def earned_rewards(state, functions) -> list:
    """The reward functions earned since the last call, in the order earned, each as ``(function id,
    context)``: the player at its position (AdvancementRewards.grant runs it with the player's
    CommandSourceStack). When and how they run is the caller's (ServerFunctionManager.execute:
    inside a running command, queued to run right after that command, one frame deeper; else a
    root of its own). A function that is not loaded is an error and runs nothing."""
    earned, state.pending_rewards = state.pending_rewards, []
    out = []
    for function, player in earned:
        if function not in functions:
            state.error(f"advancement reward function {function} does not exist")
            continue
        out.append((function, entity_context(state, player)))
    return out


def broadcast_changes(env, players) -> None:
    """ServerPlayer.containerMenu.broadcastChanges after a command changed the players' inventories:
    their changed slots fire inventory_changed now."""
    for player in players:
        if player.is_player:
            advancements.broadcast_changes(env.state, player)


def _perform(state, action: str, player, advancement_id: str) -> bool:
    """Action.GRANT: false when done, else award every remaining criterion; REVOKE: false without
    progress, else revoke every obtained criterion."""
    names = list(criteria(state.resources.advancements[advancement_id]))
    got = state.advancement_progress.of(player, advancement_id)
    if action == "grant":
        if is_done(state, player, advancement_id):
            return False
        for name in [n for n in names if n not in got]:
            advancements.award(state, player, advancement_id, name)
        return True
    if not got:
        return False
    for name in list(got):
        advancements.revoke(state, player, advancement_id, name)
    return True


def _read(cmd: ast.GenericCommand):
    """(action, targets, mode, advancement id or None, criterion or None)."""
    reader = Reader(cmd.text, cmd.loc, (1, 21, 0))
    words = cmd.text.split()
    try:
        if len(words) < 4 or words[1] not in ("grant", "revoke"):
            raise ParseError("expected 'advancement grant|revoke TARGETS MODE ...'", 0)
        reader.pos = len(words[0]) + len(words[1]) + 2
        if reader.text.startswith("@", reader.pos):
            targets = selectors.selector(reader)
            rest = reader.text[reader.pos:].split()
        else:
            targets = holder_from_word(words[2], cmd.loc)
            rest = words[3:]
    except ParseError as error:
        raise CommandFailure("dpemu.command.unreadable", "advancement", error.message, report=True) from None
    mode = rest[0] if rest else ""
    if mode == "everything" and len(rest) == 1:
        return words[1], targets, mode, None, None
    if mode not in _MODES or len(rest) < 2 or (len(rest) > 2 and mode != "only") or len(rest) > 3:
        raise CommandFailure("dpemu.command.unreadable", "advancement", f"unexpected {' '.join(rest)!r}", report=True)
    advancement_id = rest[1] if ":" in rest[1] else "minecraft:" + rest[1]
    return words[1], targets, mode, advancement_id, rest[2] if len(rest) == 3 else None


HANDLERS = {"advancement": advancement}
