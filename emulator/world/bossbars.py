"""Custom boss bars and the ``bossbar`` command (``execute store ... bossbar`` is
:mod:`emulator.commands.stores`).

Source (decompiled 1.21): server/commands/BossBarCommands.java (every subcommand, its result and its
"Nothing changed" failures), server/bossevents/CustomBossEvent.java (value 0, max 100, white,
progress, visible, no players). The name is kept as the text component written in the command (no text resolution).
"""
from __future__ import annotations

from dataclasses import dataclass, field

from emulator.commands.failure import CommandFailure
from mcfunction_parser import ast
from mcfunction_parser.pack.tags import normalise_id


@dataclass
class BossBar:
    name: str
    value: int = 0
    max: int = 100
    color: str = "white"
    style: str = "progress"
    visible: bool = True
    players: list[str] = field(default_factory=list)  # player names, in the order they were set


class BossBars(dict):
    """CustomBossEvents: full id -> :class:`BossBar`, in creation order."""

    def find(self, bar_id: str) -> BossBar:
        """BossBarCommands.getBossBar: an unknown id fails the command."""
        bar = self.get(normalise_id(bar_id))
        if bar is None:
            raise CommandFailure("commands.bossbar.unknown", normalise_id(bar_id))
        return bar


def bossbar_command(bars: BossBars, cmd: ast.Bossbar, players: list[str] | None = None) -> int:
    """One ``bossbar`` command; ``players``: the names ``set players TARGETS`` found (resolved by
    the backend; None or empty for nobody)."""
    if cmd.action == "list":
        return len(bars)
    if cmd.action == "add":
        bar_id = normalise_id(cmd.id)
        if bar_id in bars:
            raise CommandFailure("commands.bossbar.create.failed", bar_id)
        bars[bar_id] = BossBar(cmd.text)
        return len(bars)
    bar = bars.find(cmd.id)
    if cmd.action == "remove":
        del bars[normalise_id(cmd.id)]
        return len(bars)
    if cmd.action == "get":
        return _get(bar, cmd.field)
    return _set(bar, cmd, players or [])


def _get(bar: BossBar, what: str) -> int:
    if what == "visible":
        return int(bar.visible)
    if what == "players":
        return len(bar.players)
    return getattr(bar, what)  # value, max


# set FIELD: (attribute, the AST field holding the new value, the failure when unchanged,
# whether the result is the new value (value, max) or 0)
_SETTERS = {
    "name": ("name", "text", "commands.bossbar.set.name.unchanged", False),
    "color": ("color", "text", "commands.bossbar.set.color.unchanged", False),
    "style": ("style", "text", "commands.bossbar.set.style.unchanged", False),
    "value": ("value", "number", "commands.bossbar.set.value.unchanged", True),
    "max": ("max", "number", "commands.bossbar.set.max.unchanged", True),
}


def _set(bar: BossBar, cmd: ast.Bossbar, players: list[str]) -> int:
    if cmd.field == "players":  # CustomBossEvent.setPlayers: fails when the set is unchanged
        wanted = list(dict.fromkeys(players))
        if set(wanted) == set(bar.players):
            raise CommandFailure("commands.bossbar.set.players.unchanged")
        bar.players = wanted
        return len(wanted)
    if cmd.field == "visible":
        if bar.visible == cmd.flag:
            raise CommandFailure("commands.bossbar.set.visibility.unchanged." + ("visible" if cmd.flag else "hidden"))
        bar.visible = cmd.flag
        return 0
    attribute, source, unchanged, returns_value = _SETTERS[cmd.field]
    new = getattr(cmd, source)
    if getattr(bar, attribute) == new:
        raise CommandFailure(unchanged)
    setattr(bar, attribute, new)
    return new if returns_value else 0
