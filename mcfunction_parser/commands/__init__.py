"""Command parsers, one module per command family; :func:`command` dispatches on the first word."""
from __future__ import annotations

from . import bossbar, chat, data, entities, execute, functions, items, packtest, scoreboard, server
from .dispatch import PACKTEST, REGISTRY, command

for _family in (bossbar, chat, data, entities, execute, functions, items, scoreboard, server):
    REGISTRY.update(_family.PARSERS)
PACKTEST.update(packtest.PARSERS)

__all__ = ["command", "REGISTRY"]
