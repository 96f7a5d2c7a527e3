"""PackTest's ``chat PATTERN [RECEIVERS]`` condition (ChatAssertion, ChatRecorder).

PackTest records the *system* messages sent to each player (a mixin on
ServerPlayer.sendSystemMessage): one record per receiving player, so nothing without a player.
``tellraw`` (TellRawCommand: sendSystemMessage to each target player) and ``random roll``
(broadcastSystemMessage) are recorded; ``say`` is a chat message (PlayerList.broadcastChatMessage
-> sendChatMessage), which PackTest does not record. The log keeps who received each message
(``LogEntry.receivers``).
"""
from __future__ import annotations

import re

from emulator.commands import entities as world_entities
from emulator.world.errors import CommandFailure
from emulator.world.context import Context
from emulator.testing.testfile import ChatCheck

SYSTEM_MESSAGES = ("tellraw", "chat")  # log kinds sent with sendSystemMessage


class NoPlayer(Exception):
    """The receivers found no player (EntityArgument.getPlayers): the condition errs."""

    message = "No player was found"


def received(emu, check: ChatCheck, chat_start: int, ctx: Context) -> list[str]:
    """The messages since the test started, once per receiving player; with receivers, those of
    each receiver in turn (ChatRecorder.since with a recipient, flat-mapped over the players)."""
    entries = [e for e in emu.log[chat_start:] if e.kind in SYSTEM_MESSAGES]
    if check.receivers is None:
        return [e.read_text(emu.state.version) for e in entries for _ in e.receivers]
    players = [p for p in _select(emu, check.receivers, ctx) if p.is_player]
    if not players:
        raise NoPlayer()
    return [e.read_text(emu.state.version) for p in players for e in entries if p.uuid_string in e.receivers]


def matches(emu, check: ChatCheck, chat_start: int, ctx: Context) -> list[str]:
    return [m for m in received(emu, check, chat_start, ctx) if re.search(check.pattern, m)]


def holds(emu, check: ChatCheck, chat_start: int, ctx: Context) -> bool:
    """PackTestExecutor.satisfied: a match (or, negated, none and no error)."""
    try:
        return bool(matches(emu, check, chat_start, ctx)) != check.negated
    except NoPlayer:
        return False


def failure(emu, check: ChatCheck, chat_start: int, ctx: Context, sample) -> str:
    """ChatAssertion's messages (``sample`` formats the received messages)."""
    try:
        if check.negated:
            return f"Did not expect chat message matching {check.pattern}, found {len(matches(emu, check, chat_start, ctx))}"
        return f"Expected chat message matching {check.pattern}, received {sample(received(emu, check, chat_start, ctx))}"
    except NoPlayer as error:
        return error.message


def _select(emu, target, ctx: Context) -> list:
    try:
        return world_entities.select(emu.state, target, ctx)
    except CommandFailure:  # a selector the world library cannot read
        return []


