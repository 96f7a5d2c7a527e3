"""``bossbar`` (BossBarCommands, decompiled 1.21): every subcommand, its result (add/remove/list the
number of bars, set value|max the new value, set name|color|style|visible 0, set players and get
players the player count, get visible 1/0) and its "Nothing changed" failures. The bars are the
world's :mod:`emulator.world.bossbars`.
"""
from __future__ import annotations

from emulator.world.bossbars import BossBar
from mcfunction_parser import ast
from mcfunction_parser.pack.tags import normalise_id

from . import entities
from emulator.world.errors import CommandFailure


def bossbar(env, cmd: ast.Bossbar, ctx) -> int:
    """One ``bossbar`` command."""
    bars = env.state.bossbars
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
    return _set(bar, cmd, _players(env, cmd, ctx))


def _players(env, cmd: ast.Bossbar, ctx) -> list[str]:
    """``set players [TARGETS]``: EntityArgument.getOptionalPlayers (none found is not an error)."""
    if cmd.targets is None:
        return []
    return [e.player_name for e in entities.select(env.state, cmd.targets, ctx) if e.is_player]


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


HANDLERS = {ast.Bossbar: bossbar}
