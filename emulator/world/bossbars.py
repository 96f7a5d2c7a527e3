"""Custom boss bars (the ``bossbar`` command is :mod:`emulator.commands.bossbar`).

Source (decompiled 1.21): server/bossevents/CustomBossEvent.java (value 0, max 100, white,
progress, visible, no players), CustomBossEvents. The name is kept as the text component written in the command (no text resolution).
"""
from __future__ import annotations

from dataclasses import dataclass, field

from emulator.world.errors import CommandFailure
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
